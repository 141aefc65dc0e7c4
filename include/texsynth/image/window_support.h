#pragma once
// Small helpers shared by the random-access 2D synthesizers (tile-deform, tile-blend):
// option validation, window checks and wrapped sampling at far-away coordinates.
#include <cmath>
#include <cstdint>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/image.h"

namespace texsynth {

// Rows per parallel chunk: fixed, so results never depend on the thread count.
inline constexpr std::int64_t kRowChunk = 8;

// Throws ParameterError(name, ...) unless value is finite and >= minimum.
inline void requireFiniteAtLeast(const char* name, float value, float minimum) {
  if (!std::isfinite(value) || value < minimum)
    throw ParameterError(name, "must be a finite number >= " + std::to_string(minimum) + ", got " + std::to_string(value));
}
// Throws ParameterError(name, ...) unless value is finite and > 0.
inline void requireFinitePositive(const char* name, float value) {
  if (!std::isfinite(value) || !(value > 0.0f))
    throw ParameterError(name, "must be a finite number > 0, got " + std::to_string(value));
}
// Throws ParameterError("width" / "height", ...) for an empty window.
inline void requireWindow(int width, int height) {
  if (width <= 0) throw ParameterError("width", "window width must be > 0, got " + std::to_string(width));
  if (height <= 0) throw ParameterError("height", "window height must be > 0, got " + std::to_string(height));
}

// Bilinear, wrap-around sample of `image` at continuous (x, y) (pixel centers at +0.5), the
// same lookup as Image::sampleBilinearWrapped but inline and with the wrap done once in double,
// so points far from the origin keep sub-pixel precision and the hot loops stay fast.
inline void sampleWrapped(const Image& image, double x, double y, float* out) {
  const int w = image.width, h = image.height;
  double fx = x - 0.5, fy = y - 0.5;
  fx -= std::floor(fx / w) * w;
  fy -= std::floor(fy / h) * h;
  int x0 = int(fx), y0 = int(fy);
  const float tx = float(fx - x0), ty = float(fy - y0);
  if (x0 >= w) x0 -= w;  // fx may round up to exactly w
  if (y0 >= h) y0 -= h;
  const int x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == h ? 0 : y0 + 1;
  const float *p00 = image.pixel(x0, y0), *p10 = image.pixel(x1, y0);
  const float *p01 = image.pixel(x0, y1), *p11 = image.pixel(x1, y1);
  for (int c = 0; c < image.channels; ++c) {
    float top = p00[c] + (p10[c] - p00[c]) * tx;
    float bottom = p01[c] + (p11[c] - p01[c]) * tx;
    out[c] = top + (bottom - top) * ty;
  }
}

}  // namespace texsynth
