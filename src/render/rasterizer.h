#pragma once
// Internal: a tiled, deterministic z-buffer rasterizer producing a visibility buffer (which
// triangle covers each sample). Vertices are snapped to a fixed-point grid so edge tests are
// exact integer arithmetic: shared edges never crack and results never depend on threads.
#include <cstdint>
#include <vector>

#include "texsynth/core/math.h"

namespace texsynth::render_detail {

// Fixed-point sub-sample resolution: 1/256 of a sample.
inline constexpr int kSubsampleBits = 8;
inline constexpr std::int64_t kSubsampleOne = std::int64_t(1) << kSubsampleBits;

struct ScreenVertex {
  std::int64_t x = 0, y = 0;  // fixed point, y down
  float inverseDepth = 0;     // 1 / view depth; larger is nearer
};

// Snaps a projected point (screen x, y in samples, inverse depth) to the fixed-point grid.
ScreenVertex snapToGrid(const Vec3f& projected);

struct VisibilityBuffer {
  int width = 0, height = 0;
  std::vector<std::int32_t> triangle;  // per sample, row-major; -1 where nothing is drawn
  std::int32_t at(int x, int y) const { return triangle[std::size_t(y) * width + x]; }
};

// Rasterizes all triangles into a width x height sample grid. The nearest surface wins;
// on exactly equal depth the smaller triangle index wins. Zero-area triangles draw nothing.
VisibilityBuffer rasterize(const std::vector<ScreenVertex>& vertices, const std::vector<Vec3i>& triangles, int width,
                           int height);

// Screen-space (affine) barycentric weights of sample (x, y) in a triangle, from the same
// exact edge functions the rasterizer used. The triangle must have non-zero screen area.
Vec3f screenBarycentrics(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int x, int y);

}  // namespace texsynth::render_detail
