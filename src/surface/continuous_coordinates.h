#pragma once
// Continuous exemplar coordinates (surface_parallel.h): wrapping, the nearest pixel, and the
// color there. Shared by the start and the continuous E+M refinement.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

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
  const int x = wrapNear(roundHalfAway(c.x()), width), y = wrapNear(roundHalfAway(c.y()), height);
  return std::int32_t(y) * width + x;
}

// The part of a coordinate beyond its nearest pixel centre, in [-0.5, 0.5].
inline Vec2f subPixel(const Vec2f& c) {
  return Vec2f(c.x() - std::round(c.x()), c.y() - std::round(c.y()));
}

// Pixel `pixel` (y * width + x) moved by a sub-pixel part: a k-coherence candidate that keeps the
// registration of the coordinate that proposed it.
inline Vec2f atPixel(std::int32_t pixel, int width, const Vec2f& part = Vec2f::Zero()) {
  return Vec2f(float(pixel % width) + part.x(), float(pixel / width) + part.y());
}

// The level's color at (x, y), in pixel units (centres at integers), any real coordinates,
// wrapped: the nearest pixel's. Bilinear lookups would register as well but blur: at random
// sub-pixel offsets they average away about half of a fine texture's variance (GIMP burlap on
// the CGAL bunny: histogram distance 5.1 against 2.5, and the weave's threads soften).
struct NearestLookup {
  const Image& image;
  int channels;
  const float* operator()(float x, float y) const {
    return image.pixel(wrapNear(roundHalfAway(x), image.width), wrapNear(roundHalfAway(y), image.height));
  }
};

// Sum over `members` of the squared difference between each member's color (`colors`, channels
// floats per vertex) and the level at c + h * its offset: how far the members are from a coherent
// copy of the exemplar around c. Stops once the sum reaches `bound`.
template <class Members>
float stencilDistance(const NearestLookup& lookup, const float* colors, const Members& members, const Vec2f& c, float h,
                      float sum = 0.0f, float bound = std::numeric_limits<float>::infinity()) {
  const int channels = lookup.channels;
  for (const auto& m : members) {
    const float* looked = lookup(c.x() + h * m.dx, c.y() + h * m.dy);
    const float* color = colors + std::size_t(m.vertex) * std::size_t(channels);
    for (int i = 0; i < channels; ++i) sum += (looked[i] - color[i]) * (looked[i] - color[i]);
    if (sum >= bound) break;
  }
  return sum;
}

}  // namespace texsynth::surface_detail
