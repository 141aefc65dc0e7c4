#pragma once
// Shared fixtures for the solid tests: random points/normals and a small exemplar volume.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/math.h"
#include "texsynth/core/random.h"
#include "texsynth/core/volume.h"

namespace texsynth::test {

inline std::vector<Vec3f> randomPoints(int count, float extent, std::uint64_t seed = 7) {
  std::vector<Vec3f> points(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i)
    for (int a = 0; a < 3; ++a)
      points[i][a] = (uniform01(hashKey(seed, std::uint64_t(i), std::uint64_t(a))) - 0.5f) * extent;
  return points;
}

inline std::vector<Vec3f> randomNormals(int count, std::uint64_t seed = 9) {
  std::vector<Vec3f> normals = randomPoints(count, 2.0f, seed);
  for (Vec3f& n : normals) n = n.norm() > 1e-3f ? n.normalized() : Vec3f::UnitZ();
  return normals;
}

// A smooth, non-constant RGB volume (periodic, so tiling it has no seams).
inline Volume makeTestVolume(int n) {
  Volume v(n, n, n, 3);
  const float k = 6.2831853f / float(n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        v.at(x, y, z, 0) = 0.5f + 0.4f * std::sin(k * x) * std::cos(k * z);
        v.at(x, y, z, 1) = 0.5f + 0.4f * std::sin(2 * k * y + k * x);
        v.at(x, y, z, 2) = uniform01(hashKey(3, std::uint64_t((z * n + y) * n + x)));
      }
  return v;
}

}  // namespace texsynth::test
