#include "texsynth/field/field_grid.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {

void validateFieldGridOptions(const FieldGridOptions& options) {
  if (options.shortestCells < 2 || options.shortestCells > 512)
    throw ParameterError("shortestCells", "must be in [2, 512], got " + std::to_string(options.shortestCells));
  if (!(options.margin >= 0 && options.margin <= 1))
    throw ParameterError("margin", "must be in [0, 1], got " + std::to_string(options.margin));
}

std::int64_t FieldGrid::nearestNode(const Vec3f& p) const {
  Vec3f g = toGrid(p);
  int c[3];
  for (int a = 0; a < 3; ++a) c[a] = std::clamp(int(std::lround(g[a])), 0, nodes[a] - 1);
  return index(c[0], c[1], c[2]);
}

bool FieldGrid::contains(const Vec3f& p) const {
  Vec3f g = toGrid(p);
  for (int a = 0; a < 3; ++a)
    if (!(g[a] >= -1e-4f && g[a] <= float(nodes[a] - 1) + 1e-4f)) return false;
  return true;
}

FieldGrid makeFieldGrid(const Box3f& box, const FieldGridOptions& options) {
  validateFieldGridOptions(options);
  if (!box.valid() || !box.min.allFinite() || !box.max.allFinite())
    throw InputError("mesh", "has no finite bounding box");
  Vec3f size = box.size();
  const float pad = options.margin * size.maxCoeff();
  Vec3f lo = box.min - Vec3f::Constant(pad), extent = size + Vec3f::Constant(2 * pad);
  // A flat box (a planar mesh) still needs a volume: give it at least one cell of thickness.
  const float longest = extent.maxCoeff();
  if (!(longest > 0)) throw InputError("mesh", "bounding box has zero size");
  float shortest = std::max(extent.minCoeff(), longest / 512.0f);
  FieldGrid grid;
  grid.spacing = shortest / float(options.shortestCells);
  for (int a = 0; a < 3; ++a) {
    int cells = std::max(options.shortestCells, int(std::ceil(extent[a] / grid.spacing - 1e-3f)));
    if (cells > 4096) throw ParameterError("shortestCells", "the grid would have more than 4096 cells along one side");
    grid.nodes[a] = cells + 1;
    // Centre the grid on the box so the margin is the same on both sides.
    lo[a] -= 0.5f * (float(cells) * grid.spacing - extent[a]);
  }
  grid.origin = lo;
  // Far beyond any interactive use (the paper's grids have 20-30 cells a side), and memory.
  if (grid.nodeCount() > (std::int64_t(1) << 26))
    throw ParameterError("shortestCells", "the grid would have " + std::to_string(grid.nodeCount()) +
                                              " nodes (limit 67108864); use fewer cells");
  return grid;
}

FieldGrid::Corners FieldGrid::corners(const Vec3f& p) const {
  const Vec3f g = toGrid(p);
  int base[3];
  float t[3];
  for (int a = 0; a < 3; ++a) {
    const float c = std::clamp(g[a], 0.0f, float(nodes[a] - 1));
    base[a] = std::min(int(c), nodes[a] - 2);
    t[a] = c - float(base[a]);
  }
  Corners out;
  for (int corner = 0; corner < 8; ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
    out.node[corner] = index(base[0] + dx, base[1] + dy, base[2] + dz);
    out.weight[corner] = (dx ? t[0] : 1 - t[0]) * (dy ? t[1] : 1 - t[1]) * (dz ? t[2] : 1 - t[2]);
  }
  return out;
}

FieldGrid coarserGrid(const FieldGrid& grid) {
  FieldGrid coarse;
  coarse.origin = grid.origin;
  coarse.spacing = grid.spacing * 2;
  for (int a = 0; a < 3; ++a) coarse.nodes[a] = std::max(2, grid.nodes[a] / 2 + 1);
  return coarse;
}

}  // namespace texsynth
