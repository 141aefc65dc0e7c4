#include "demo_fallbacks.h"

#include <cmath>
#include <map>

#include "texsynth/core/random.h"

namespace texsynth::cli {

// Smooth value noise on a lattice with period `period` (so the texture tiles).
static float valueNoise(float x, float y, int period, std::uint64_t seed) {
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float tx = x - x0, ty = y - y0;
  tx = tx * tx * (3 - 2 * tx), ty = ty * ty * (3 - 2 * ty);
  auto corner = [&](int i, int j) {
    int wi = ((x0 + i) % period + period) % period, wj = ((y0 + j) % period + period) % period;
    return uniform01(hashKey(seed, latticeId(wi, wj)));
  };
  float top = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * tx;
  float bottom = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * tx;
  return top + (bottom - top) * ty;
}

Image proceduralMarble(int size, std::uint64_t seed) {
  Image image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float turbulence = 0, amplitude = 1;
      for (int octave = 0; octave < 5; ++octave) {
        int period = 4 << octave;
        float scale = float(period) / size;
        turbulence += amplitude * std::abs(valueNoise(x * scale, y * scale, period, seed + octave) - 0.5f);
        amplitude *= 0.5f;
      }
      float vein = 0.5f + 0.5f * std::sin(2.0f * float(M_PI) * (2.0f * x / size + 3.0f * turbulence));
      float v = std::pow(vein, 0.6f);
      image.at(x, y, 0) = 0.35f + 0.6f * v;
      image.at(x, y, 1) = 0.33f + 0.55f * v;
      image.at(x, y, 2) = 0.30f + 0.5f * v;
    }
  return image;
}

Mesh icosphere(int subdivisions) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  Mesh mesh;
  mesh.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto [it, inserted] = midpoints.try_emplace({key.first, key.second}, int(mesh.positions.size()));
      if (inserted) mesh.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
      return it->second;
    };
    std::vector<Vec3i> finer;
    for (const Vec3i& f : mesh.triangles) {
      int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(finer);
  }
  for (Vec3f& p : mesh.positions) p.normalize();
  mesh.computeNormals();
  return mesh;
}

}  // namespace texsynth::cli
