// Exact signed Euclidean distance of a binary volume, by the separable squared-distance transform
// (lower envelope of parabolas along x, then y, then z).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "texsynth/core/parallel.h"
#include "texsynth/gradient/vectorize.h"

namespace texsynth {
namespace {

constexpr float kFar = 1e20f;

// In place along one line of `n` samples `stride` apart: f[i] <- min_j (f[j] + (i-j)^2).
void distanceTransformLine(float* f, int n, std::size_t stride, std::vector<float>& line, std::vector<int>& vertex,
                           std::vector<float>& boundary) {
  line.resize(std::size_t(n));
  vertex.resize(std::size_t(n));
  boundary.resize(std::size_t(n) + 1);
  for (int i = 0; i < n; ++i) line[std::size_t(i)] = f[std::size_t(i) * stride];
  int k = 0;
  vertex[0] = 0;
  boundary[0] = -kFar;
  boundary[1] = kFar;
  for (int q = 1; q < n; ++q) {
    float s;
    while (true) {
      const int v = vertex[std::size_t(k)];
      s = ((line[std::size_t(q)] + float(q) * q) - (line[std::size_t(v)] + float(v) * v)) / (2.0f * float(q - v));
      if (s > boundary[std::size_t(k)] || k == 0) break;
      --k;
    }
    if (s <= boundary[std::size_t(k)]) {  // k == 0 and the new parabola hides the first one everywhere
      vertex[0] = q;
      boundary[1] = kFar;
      continue;
    }
    ++k;
    vertex[std::size_t(k)] = q;
    boundary[std::size_t(k)] = s;
    boundary[std::size_t(k) + 1] = kFar;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (boundary[std::size_t(k) + 1] < float(q)) ++k;
    const int v = vertex[std::size_t(k)];
    f[std::size_t(q) * stride] = float(q - v) * float(q - v) + line[std::size_t(v)];
  }
}

// Squared distance from every voxel to the nearest voxel where `seed` is true.
std::vector<float> squaredDistance(const Volume& mask, bool seedInside) {
  const int nx = mask.nx, ny = mask.ny, nz = mask.nz;
  std::vector<float> f(mask.voxelCount());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = ((mask.voxels[i] > 0.5f) == seedInside) ? 0.0f : kFar;
  const std::size_t sx = 1, sy = std::size_t(nx), sz = std::size_t(nx) * ny;
  auto pass = [&](int lines, int n, std::size_t stride, auto start) {
    parallelForChunks(0, lines, 64, [&](std::int64_t begin, std::int64_t end) {
      std::vector<float> line, boundary;
      std::vector<int> vertex;
      for (std::int64_t l = begin; l < end; ++l) distanceTransformLine(&f[start(l)], n, stride, line, vertex, boundary);
    });
  };
  pass(ny * nz, nx, sx, [&](std::int64_t l) { return std::size_t(l) * sy; });
  pass(nx * nz, ny, sy, [&](std::int64_t l) { return std::size_t(l / nx) * sz + std::size_t(l % nx); });
  pass(nx * ny, nz, sz, [&](std::int64_t l) { return std::size_t(l); });
  return f;
}

}  // namespace

Volume signedDistanceVolume(const Volume& mask, float limit) {
  TS_CHECK(mask.channels == 1);
  const std::vector<float> toInside = squaredDistance(mask, true), toOutside = squaredDistance(mask, false);
  Volume distance(mask.nx, mask.ny, mask.nz, 1);
  for (std::size_t i = 0; i < distance.voxels.size(); ++i) {
    // The boundary lies half way between a voxel centre and its nearest centre on the other side.
    const bool inside = mask.voxels[i] > 0.5f;
    const float d = std::sqrt(inside ? toOutside[i] : toInside[i]) - 0.5f;
    distance.voxels[i] = std::clamp(inside ? d : -d, -limit, limit);
  }
  return distance;
}

}  // namespace texsynth
