#pragma once
// Colour helpers shared by images, volumes and solids.
#include <cmath>

namespace texsynth {

// The sRGB transfer function (IEC 61966-2-1), for formats that store linear colours (glTF's
// COLOR_0) while texsynth's colours, like its images, are sRGB-encoded.
// Values beyond 1 map to 1, so white stays exactly white both ways.
inline float srgbToLinear(float c) {
  return c >= 1.0f ? 1.0f : c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
inline float linearToSrgb(float c) {
  return c >= 1.0f ? 1.0f : c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Rec. 709 luminance of interleaved values: of the first three channels when there are three or more,
// else the first channel itself (gray, or gray + alpha).
inline float luminance(const float* values, int channels) {
  return channels >= 3 ? 0.2126f * values[0] + 0.7152f * values[1] + 0.0722f * values[2] : values[0];
}

}  // namespace texsynth
