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

// Carries the values of side `sign` into the other side's voxels up to `rings` voxels (Chebyshev) from
// the boundary, one ring of 26-neighbours at a time, each voxel taking the mean of its neighbours valued
// in earlier rings (a dilation, §4.3). Other voxels keep their own values.
Volume dilateSide(const Volume& colors, const Volume& mask, const Volume& distance, int sign, int rings) {
  Volume out = colors;
  const int c = colors.channels;
  const std::int64_t nx = mask.nx, ny = mask.ny, nz = mask.nz;
  std::vector<std::uint8_t> valued(mask.voxelCount()), queued(mask.voxelCount(), 0);
  for (std::size_t v = 0; v < valued.size(); ++v) valued[v] = insideMask(mask, v) == (sign > 0);
  auto forNeighbours = [&](std::int64_t v, auto f) {
    const std::int64_t x = v % nx, y = (v / nx) % ny, z = v / (nx * ny);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const std::int64_t qx = x + dx, qy = y + dy, qz = z + dz;
          if ((dx | dy | dz) == 0 || qx < 0 || qy < 0 || qz < 0 || qx >= nx || qy >= ny || qz >= nz) continue;
          f((qz * ny + qy) * nx + qx);
        }
  };
  // The first ring: the other side's voxels touching this side. A 26-neighbour is at most sqrt(3) away, so
  // only voxels that close to the boundary (|signed distance| <= sqrt(3) - 1/2) need looking at.
  std::vector<std::int64_t> ring;
  for (std::int64_t v = 0; v < std::int64_t(valued.size()); ++v)
    if (!valued[std::size_t(v)] && std::abs(distance.voxels[std::size_t(v)]) <= 1.25f) {
      bool touches = false;
      forNeighbours(v, [&](std::int64_t q) { touches = touches || valued[std::size_t(q)]; });
      if (touches) ring.push_back(v), queued[std::size_t(v)] = 1;
    }
  std::vector<float> values;
  for (int r = 0; r < rings && !ring.empty(); ++r) {
    values.assign(ring.size() * std::size_t(c), 0.0f);
    parallelForChunks(0, std::int64_t(ring.size()), 1024, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t n = begin; n < end; ++n) {
        float* sum = &values[std::size_t(n) * std::size_t(c)];
        int count = 0;
        forNeighbours(ring[std::size_t(n)], [&](std::int64_t q) {
          if (!valued[std::size_t(q)]) return;
          ++count;
          for (int ch = 0; ch < c; ++ch) sum[ch] += out.voxels[std::size_t(q) * std::size_t(c) + std::size_t(ch)];
        });
        for (int ch = 0; ch < c; ++ch) sum[ch] /= float(count);
      }
    });
    for (std::size_t n = 0; n < ring.size(); ++n) {
      std::copy_n(&values[n * std::size_t(c)], c, &out.voxels[std::size_t(ring[n]) * std::size_t(c)]);
      valued[std::size_t(ring[n])] = 1;
    }
    std::vector<std::int64_t> next;
    for (std::int64_t v : ring)
      forNeighbours(v, [&](std::int64_t q) {
        if (valued[std::size_t(q)] || queued[std::size_t(q)]) return;
        queued[std::size_t(q)] = 1;
        next.push_back(q);
      });
    ring.swap(next);
  }
  return out;
}

}  // namespace

Regions separateRegions(const ControlGrid& grid, const Volume& colors, const Volume& mask) {
  Regions regions;
  // Distances are kept to 3 cubes: enough for the sign near the boundary, and small numbers to store.
  const float limit = 3.0f * float(grid.spacing);
  regions.signedDistance = signedDistanceVolume(mask, limit);
  regions.cubeSides = cubeSidesOf(grid, mask);
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
  regions.positive = dilateSide(colors, mask, regions.signedDistance, 1, rings);
  regions.negative = dilateSide(colors, mask, regions.signedDistance, -1, rings);
  return regions;
}

}  // namespace texsynth::vectorize_detail
