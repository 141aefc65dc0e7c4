#include "vectorize_regions.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/parallel.h"
#include "texsynth/gradient/vectorize.h"

namespace texsynth::vectorize_detail {
namespace {

bool insideMask(const Volume& mask, std::size_t voxel) {
  return mask.voxels[voxel] > 0.5f;
}

// Which sides each cube's closed lattice of voxels (its far faces included) touches.
std::vector<CubeSides> cubeSidesOf(const ControlGrid& grid, const Volume& mask) {
  std::vector<CubeSides> sides(std::size_t(grid.cubeCount()));
  parallelFor(0, grid.cubes(2), [&](std::int64_t k) {
    for (int j = 0; j < grid.cubes(1); ++j)
      for (int i = 0; i < grid.cubes(0); ++i) {
        const int index[3] = {i, j, int(k)};
        int begin[3], end[3];
        for (int a = 0; a < 3; ++a)
          begin[a] = grid.cubeBegin(a, index[a]), end[a] = std::min(grid.cubeEnd(a, index[a]) + 1, grid.voxels[a]);
        bool positive = false, negative = false;
        for (int z = begin[2]; z < end[2]; ++z)
          for (int y = begin[1]; y < end[1]; ++y)
            for (int x = begin[0]; x < end[0]; ++x)
              (insideMask(mask, mask.index(x, y, z)) ? positive : negative) = true;
        sides[std::size_t(grid.cubeIndex(i, j, int(k)))] = positive && negative ? CubeSides::Both
                                                           : positive           ? CubeSides::Positive
                                                                                : CubeSides::Negative;
      }
  });
  return sides;
}

// Chessboard (26-neighbour) distance from every voxel to the nearest voxel of side `sign`, capped at
// `cap`: separable, one pass per axis, each line independent.
std::vector<std::uint8_t> chessboardDistance(const Volume& mask, int sign, int cap) {
  const int n[3] = {mask.nx, mask.ny, mask.nz};
  const std::size_t stride[3] = {1, std::size_t(n[0]), std::size_t(n[0]) * std::size_t(n[1])};
  std::vector<std::uint8_t> d(mask.voxelCount());
  for (std::size_t v = 0; v < d.size(); ++v) d[v] = insideMask(mask, v) == (sign > 0) ? 0 : std::uint8_t(cap);
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const int length = n[axis], lines1 = n[a1];
    const std::size_t step = stride[axis], step1 = stride[a1], step2 = stride[a2];
    parallelFor(0, std::int64_t(lines1) * n[a2], [&d, length, lines1, step, step1, step2](std::int64_t line) {
      const std::size_t start = std::size_t(line % lines1) * step1 + std::size_t(line / lines1) * step2;
      std::vector<std::uint8_t> in(static_cast<std::size_t>(length));
      for (int i = 0; i < length; ++i) in[std::size_t(i)] = d[start + std::size_t(i) * step];
      for (int i = 0; i < length; ++i) {  // min over k of max(|k|, in[i + k])
        int best = in[std::size_t(i)];
        for (int k = 1; k < best; ++k) {
          if (i - k >= 0) best = std::min(best, std::max(k, int(in[std::size_t(i - k)])));
          if (i + k < length) best = std::min(best, std::max(k, int(in[std::size_t(i + k)])));
        }
        d[start + std::size_t(i) * step] = std::uint8_t(best);
      }
    });
  }
  return d;
}

// Carries the values of side `sign` into the other side's voxels up to `rings` voxels (chessboard
// distance) from it, ring by ring, each voxel taking the mean of its 26-neighbours in nearer rings (a
// dilation, §4.3). Other voxels keep their own values. A ring's voxels read only nearer rings, so each
// ring runs in parallel, in place.
Volume dilateSide(const Volume& colors, const Volume& mask, int sign, int rings) {
  Volume out = colors;
  const int c = colors.channels;
  const std::vector<std::uint8_t> ring = chessboardDistance(mask, sign, rings + 1);
  const std::int64_t nx = mask.nx, ny = mask.ny, nz = mask.nz;
  // Each ring's voxels, collected per z-slice and joined in order (the same lists at any thread count).
  std::vector<std::vector<std::vector<std::int64_t>>> slices{std::size_t(nz)};
  parallelFor(0, nz, [&](std::int64_t z) {
    auto& lists = slices[std::size_t(z)];
    lists.resize(std::size_t(rings) + 1);
    for (std::int64_t v = z * nx * ny; v < (z + 1) * nx * ny; ++v)
      if (ring[std::size_t(v)] >= 1 && ring[std::size_t(v)] <= rings) lists[ring[std::size_t(v)]].push_back(v);
  });
  for (int r = 1; r <= rings; ++r) {
    std::vector<std::int64_t> voxels;
    for (const auto& lists : slices)
      voxels.insert(voxels.end(), lists[std::size_t(r)].begin(), lists[std::size_t(r)].end());
    parallelForChunks(0, std::int64_t(voxels.size()), 1024, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t i = begin; i < end; ++i) {
        const std::int64_t v = voxels[std::size_t(i)];
        const std::int64_t x = v % nx, y = (v / nx) % ny, z = v / (nx * ny);
        float sum[4] = {0, 0, 0, 0};
        int count = 0;
        for (std::int64_t dz = -1; dz <= 1; ++dz)
          for (std::int64_t dy = -1; dy <= 1; ++dy)
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
              const std::int64_t qx = x + dx, qy = y + dy, qz = z + dz;
              if (qx < 0 || qy < 0 || qz < 0 || qx >= nx || qy >= ny || qz >= nz) continue;
              const std::size_t q = std::size_t((qz * ny + qy) * nx + qx);
              if (ring[q] >= r) continue;
              ++count;
              for (int ch = 0; ch < c; ++ch) sum[ch] += out.voxels[q * std::size_t(c) + std::size_t(ch)];
            }
        for (int ch = 0; ch < c; ++ch)
          out.voxels[std::size_t(v) * std::size_t(c) + std::size_t(ch)] = sum[ch] / float(count);
      }
    });
  }
  return out;
}

}  // namespace

Regions separateRegions(const ControlGrid& grid, const Volume& colors, const Volume& sides) {
  Regions regions;
  regions.cubeSides = cubeSidesOf(grid, sides);
  regions.negativeIndex.assign(std::size_t(grid.controlCount()), -1);
  for (int k = 0; k < grid.cubes(2); ++k)
    for (int j = 0; j < grid.cubes(1); ++j)
      for (int i = 0; i < grid.cubes(0); ++i) {
        if (regions.cubeSides[std::size_t(grid.cubeIndex(i, j, k))] != CubeSides::Both) continue;
        for (int c = 0; c < 8; ++c)
          regions.negativeIndex[std::size_t(grid.controlIndex(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)))] =
              0;  // marked; numbered below in control order
      }
  for (std::int32_t& index : regions.negativeIndex)
    if (index == 0) index = std::int32_t(regions.negatives++);
  // A boundary control's bucket reaches 1.5 cubes (Chebyshev) from the boundary.
  const int rings = (3 * grid.spacing + 1) / 2 + 1;
  regions.positive = dilateSide(colors, sides, 1, rings);
  regions.negative = dilateSide(colors, sides, -1, rings);
  return regions;
}

}  // namespace texsynth::vectorize_detail
