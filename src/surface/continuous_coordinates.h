#pragma once
// Continuous exemplar coordinates (surface_parallel.h): wrapping, the nearest pixel, and the
// color there. Shared by the start and the continuous E+M refinement.
#include <cmath>
#include <cstdint>

#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/core/wrap.h"

namespace texsynth::surface_detail {

inline float wrapCoordinate(float v, int n) {
  v = std::fmod(v, float(n));
  if (v < 0) v += float(n);
  return v >= float(n) ? 0.0f : v;
}

inline Vec2f wrapCoordinates(const Vec2f& c, int width, int height) {
  return Vec2f(wrapCoordinate(c.x(), width), wrapCoordinate(c.y(), height));
}

inline std::int32_t nearestPixel(const Vec2f& c, int width, int height) {
  const int x = wrapIndex(int(std::lround(c.x())), width), y = wrapIndex(int(std::lround(c.y())), height);
  return std::int32_t(y) * width + x;
}

// The level's color at (x, y), in pixel units (centres at integers), any real coordinates,
// wrapped: the nearest pixel's. Bilinear lookups would register as well but blur: at random
// sub-pixel offsets they average away about half of a fine texture's variance (GIMP burlap on
// the CGAL bunny: histogram distance 5.1 against 2.5, and the weave's threads soften).
struct NearestLookup {
  const Image& image;
  int channels;
  const float* operator()(float x, float y) const {
    return image.pixel(wrapIndex(int(std::lround(x)), image.width), wrapIndex(int(std::lround(y)), image.height));
  }
};

}  // namespace texsynth::surface_detail
