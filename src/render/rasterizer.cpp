#include "rasterizer.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/parallel.h"

namespace texsynth::render_detail {

namespace {

// Square tiles of samples: each is rasterized by one task, with its triangles binned first.
constexpr int kTileSize = 32;

// Fixed-point coordinate of the centre of sample i.
constexpr std::int64_t sampleCenter(int i) {
  return std::int64_t(i) * kSubsampleOne + kSubsampleOne / 2;
}

// Twice the signed area of (a, b, p); positive when p lies to the right of a->b with y down.
// Exact in 64-bit integers, so E(a,b,p) == -E(b,a,p) and shared edges are watertight.
std::int64_t edge(const ScreenVertex& a, const ScreenVertex& b, std::int64_t px, std::int64_t py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

// The sample rectangle (inclusive) whose centres lie in a triangle's bounding box, clipped
// to the image; empty for zero-area triangles.
struct SampleBox {
  int minX = 0, minY = 0, maxX = -1, maxY = -1;
  bool empty() const { return maxX < minX || maxY < minY; }
};

SampleBox sampleBox(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int width, int height) {
  if (edge(a, b, c.x, c.y) == 0) return {};
  auto firstSample = [](std::int64_t low) { return -floorDiv(kSubsampleOne / 2 - low, kSubsampleOne); };
  auto lastSample = [](std::int64_t high) { return floorDiv(high - kSubsampleOne / 2, kSubsampleOne); };
  SampleBox box;
  box.minX = int(std::max<std::int64_t>(0, firstSample(std::min({a.x, b.x, c.x}))));
  box.minY = int(std::max<std::int64_t>(0, firstSample(std::min({a.y, b.y, c.y}))));
  box.maxX = int(std::min<std::int64_t>(width - 1, lastSample(std::max({a.x, b.x, c.x}))));
  box.maxY = int(std::min<std::int64_t>(height - 1, lastSample(std::max({a.y, b.y, c.y}))));
  return box;
}

struct TileGrid {
  int columns, rows;
  std::vector<std::int64_t> offsets;      // per tile, into triangleIds; size tiles + 1
  std::vector<std::int32_t> triangleIds;  // per tile, ascending triangle index
};

// Bins every drawable triangle into the tiles its sample box overlaps. Serial counting and
// filling keep each tile's list in ascending triangle order, which the depth tie-break needs.
TileGrid binTriangles(const std::vector<SampleBox>& boxes, int width, int height) {
  TileGrid grid;
  grid.columns = (width + kTileSize - 1) / kTileSize;
  grid.rows = (height + kTileSize - 1) / kTileSize;
  const std::size_t tiles = std::size_t(grid.columns) * grid.rows;
  std::vector<std::int64_t> counts(tiles + 1, 0);
  auto forEachTile = [&](const SampleBox& box, auto&& visit) {
    for (int ty = box.minY / kTileSize; ty <= box.maxY / kTileSize; ++ty)
      for (int tx = box.minX / kTileSize; tx <= box.maxX / kTileSize; ++tx) visit(std::size_t(ty) * grid.columns + tx);
  };
  for (const SampleBox& box : boxes)
    if (!box.empty()) forEachTile(box, [&](std::size_t tile) { ++counts[tile + 1]; });
  for (std::size_t t = 0; t < tiles; ++t) counts[t + 1] += counts[t];
  grid.offsets = counts;
  grid.triangleIds.resize(std::size_t(counts[tiles]));
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (!boxes[i].empty())
      forEachTile(boxes[i], [&](std::size_t tile) { grid.triangleIds[counts[tile]++] = std::int32_t(i); });
  return grid;
}

// Draws one triangle into one tile's depth/id buffers (tile-local, row stride kTileSize).
void drawTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, std::int32_t id,
                  const SampleBox& box, int tileX0, int tileY0, float* depth, std::int32_t* ids) {
  std::int64_t area = edge(a, b, c.x, c.y);
  const std::int64_t sign = area > 0 ? 1 : -1;  // two-sided: accept either winding
  area *= sign;
  const float inverseArea = 1.0f / float(area);
  const std::int64_t px = sampleCenter(box.minX), py = sampleCenter(box.minY);
  // Edge values at the box's first sample, and their exact steps per sample in x and y.
  std::int64_t row0 = sign * edge(b, c, px, py), row1 = sign * edge(c, a, px, py), row2 = sign * edge(a, b, px, py);
  const std::int64_t stepX0 = -sign * (c.y - b.y) * kSubsampleOne, stepY0 = sign * (c.x - b.x) * kSubsampleOne;
  const std::int64_t stepX1 = -sign * (a.y - c.y) * kSubsampleOne, stepY1 = sign * (a.x - c.x) * kSubsampleOne;
  const std::int64_t stepX2 = -sign * (b.y - a.y) * kSubsampleOne, stepY2 = sign * (b.x - a.x) * kSubsampleOne;
  for (int y = box.minY; y <= box.maxY; ++y) {
    std::int64_t w0 = row0, w1 = row1, w2 = row2;
    float* depthRow = depth + std::size_t(y - tileY0) * kTileSize - tileX0;
    std::int32_t* idRow = ids + std::size_t(y - tileY0) * kTileSize - tileX0;
    for (int x = box.minX; x <= box.maxX; ++x) {
      // Inclusive test: a sample exactly on a shared edge is claimed by both sides and
      // the depth test (then the index) decides, so there are never cracks.
      if ((w0 | w1 | w2) >= 0) {
        float inverseDepth =
            (float(w0) * a.inverseDepth + float(w1) * b.inverseDepth + float(w2) * c.inverseDepth) * inverseArea;
        // Strictly nearer only: triangles arrive in ascending index, so ties keep the smaller.
        if (inverseDepth > depthRow[x]) {
          depthRow[x] = inverseDepth;
          idRow[x] = id;
        }
      }
      w0 += stepX0, w1 += stepX1, w2 += stepX2;
    }
    row0 += stepY0, row1 += stepY1, row2 += stepY2;
  }
}

}  // namespace

ScreenVertex snapToGrid(const Vec3f& projected) {
  // The fitted camera keeps the mesh on screen; the bound only keeps the integer edge
  // functions (products of coordinate differences) below 2^62 should a caller ever
  // project something far outside.
  constexpr double kLimit = double(std::int64_t(1) << 29);
  auto snap = [&](float v) {
    return std::int64_t(std::llround(std::clamp(double(v) * double(kSubsampleOne), -kLimit, kLimit)));
  };
  return {snap(projected.x()), snap(projected.y()), projected.z()};
}

VisibilityBuffer rasterize(const std::vector<ScreenVertex>& vertices, const std::vector<Vec3i>& triangles, int width,
                           int height) {
  std::vector<SampleBox> boxes(triangles.size());
  parallelForChunks(0, std::int64_t(triangles.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) {
      const Vec3i& t = triangles[i];
      boxes[i] = sampleBox(vertices[t[0]], vertices[t[1]], vertices[t[2]], width, height);
    }
  });
  TileGrid grid = binTriangles(boxes, width, height);

  VisibilityBuffer buffer;
  buffer.width = width;
  buffer.height = height;
  buffer.triangle.assign(std::size_t(width) * height, -1);
  parallelFor(0, std::int64_t(grid.columns) * grid.rows, [&](std::int64_t tile) {
    const int tileX0 = int(tile % grid.columns) * kTileSize, tileY0 = int(tile / grid.columns) * kTileSize;
    const int tileX1 = std::min(width, tileX0 + kTileSize) - 1, tileY1 = std::min(height, tileY0 + kTileSize) - 1;
    float depth[kTileSize * kTileSize];
    std::int32_t ids[kTileSize * kTileSize];
    std::fill(std::begin(depth), std::end(depth), 0.0f);  // inverse depth 0: infinitely far
    std::fill(std::begin(ids), std::end(ids), -1);
    for (std::int64_t k = grid.offsets[tile]; k < grid.offsets[tile + 1]; ++k) {
      const std::int32_t id = grid.triangleIds[k];
      SampleBox box = boxes[id];
      box.minX = std::max(box.minX, tileX0), box.maxX = std::min(box.maxX, tileX1);
      box.minY = std::max(box.minY, tileY0), box.maxY = std::min(box.maxY, tileY1);
      if (box.empty()) continue;
      const Vec3i& t = triangles[id];
      drawTriangle(vertices[t[0]], vertices[t[1]], vertices[t[2]], id, box, tileX0, tileY0, depth, ids);
    }
    for (int y = tileY0; y <= tileY1; ++y)
      std::copy_n(ids + std::size_t(y - tileY0) * kTileSize, tileX1 - tileX0 + 1,
                  buffer.triangle.begin() + std::ptrdiff_t(std::size_t(y) * width + tileX0));
  });
  return buffer;
}

Vec3f screenBarycentrics(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int x, int y) {
  const std::int64_t px = sampleCenter(x), py = sampleCenter(y);
  const float inverseArea = 1.0f / float(edge(a, b, c.x, c.y));
  return {float(edge(b, c, px, py)) * inverseArea, float(edge(c, a, px, py)) * inverseArea,
          float(edge(a, b, px, py)) * inverseArea};
}

}  // namespace texsynth::render_detail
