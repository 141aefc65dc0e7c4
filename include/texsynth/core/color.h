#pragma once
// Colour helpers shared by images, volumes and solids.

namespace texsynth {

// Rec. 709 luminance of interleaved values: of the first three channels when there are three or more,
// else the first channel itself (gray, or gray + alpha).
inline float luminance(const float* values, int channels) {
  return channels >= 3 ? 0.2126f * values[0] + 0.7152f * values[1] + 0.0722f * values[2] : values[0];
}

}  // namespace texsynth
