#pragma once
// The regular grid a field lives on: nodes at origin + spacing * (i, j, k), covering a mesh's
// bounding box plus a margin, with cubic cells (one spacing on every axis).
#include <cstdint>

#include "texsynth/core/math.h"

namespace texsynth {

struct FieldGridOptions {
  // Cells along the shortest side of the (margin-enlarged) box; the paper uses 20-30.
  // In [2, 512]; the other sides get as many cells as keep the cells cubic.
  int shortestCells = 24;
  // Empty space added on every side, as a fraction of the box's longest side; in [0, 1].
  float margin = 0.05f;
};

// Throws ParameterError("shortestCells" / "margin", ...) for values outside their ranges.
void validateFieldGridOptions(const FieldGridOptions& options);

struct FieldGrid {
  Vec3f origin = Vec3f::Zero();
  float spacing = 1;
  Vec3i nodes = Vec3i::Ones();  // node count per axis (cells + 1), each >= 2

  std::int64_t nodeCount() const { return std::int64_t(nodes.x()) * nodes.y() * nodes.z(); }
  std::int64_t index(int i, int j, int k) const { return (std::int64_t(k) * nodes.y() + j) * nodes.x() + i; }
  Vec3i coordinates(std::int64_t index) const {
    return {int(index % nodes.x()), int(index / nodes.x() % nodes.y()),
            int(index / (std::int64_t(nodes.x()) * nodes.y()))};
  }
  Vec3f position(int i, int j, int k) const { return origin + spacing * Vec3f(float(i), float(j), float(k)); }
  Vec3f position(std::int64_t index) const {
    Vec3i c = coordinates(index);
    return position(c.x(), c.y(), c.z());
  }
  // Continuous grid coordinates of a world point (node i at i).
  Vec3f toGrid(const Vec3f& p) const { return (p - origin) / spacing; }
  Box3f bounds() const {
    Box3f box;
    box.extend(origin);
    box.extend(position(nodes.x() - 1, nodes.y() - 1, nodes.z() - 1));
    return box;
  }
  // The 8 nodes of the cell holding a world point (clamped to the grid), corner c at offset
  // (c & 1, c >> 1 & 1, c >> 2), with their trilinear weights (summing to 1).
  struct Corners {
    std::int64_t node[8];
    float weight[8];
  };
  Corners corners(const Vec3f& p) const;
  // The nearest node to a world point, clamped to the grid.
  std::int64_t nearestNode(const Vec3f& p) const;
  // True if p lies inside the grid's box (with a relative tolerance of 1e-4 cells).
  bool contains(const Vec3f& p) const;
};

// A grid covering `box` plus the margin. Throws ParameterError for bad options and
// InputError("mesh", ...) for an empty or non-finite box.
FieldGrid makeFieldGrid(const Box3f& box, const FieldGridOptions& options = {});

// The grid with half the resolution covering the same box (node 2i of this grid is node i of
// the coarse one; one extra coarse node where the count is even). Used by multigrid and by
// downsampled fields.
FieldGrid coarserGrid(const FieldGrid& grid);

}  // namespace texsynth
