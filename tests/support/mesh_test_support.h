#pragma once
// Meshes for the geometry and surface tests: a closed icosphere and an open square grid built in code (no
// data needed), and the CGAL demo meshes when installed.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "texsynth/core/data_paths.h"
#include "texsynth/core/mesh.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth::test {

// A unit icosahedron subdivided `subdivisions` times (10 * 4^s + 2 vertices), vertices shared,
// counter-clockwise seen from outside: closed and manifold.
inline Mesh icosphere(int subdivisions) {
  const float g = (1.0f + std::sqrt(5.0f)) / 2;
  Mesh mesh;
  mesh.positions = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  mesh.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Vec3f& p : mesh.positions) p.normalize();
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> middle;
    auto midpoint = [&](int a, int b) {
      auto [it, added] = middle.try_emplace({std::min(a, b), std::max(a, b)}, int(mesh.positions.size()));
      if (added) mesh.positions.push_back((mesh.positions[a] + mesh.positions[b]).normalized());
      return it->second;
    };
    std::vector<Vec3i> finer;
    for (const Vec3i& t : mesh.triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.insert(finer.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(finer);
  }
  mesh.computeNormals();
  return mesh;
}

// icosphere(subdivisions) with every vertex moved along the sphere by up to about a third of an
// edge (deterministically): a closed mesh with irregular edges, like a scanned one.
inline Mesh irregularSphere(int subdivisions) {
  Mesh mesh = icosphere(subdivisions);
  const float step = 0.35f * 1.1f / float(1 << subdivisions);  // ~ a third of an edge
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const float a = std::sin(12.9898f * float(v)) * 43758.5453f, b = std::sin(78.233f * float(v)) * 12543.1234f;
    const Vec3f jitter(a - std::floor(a) - 0.5f, b - std::floor(b) - 0.5f, 0);
    const Vec3f p = mesh.positions[v];
    const Vec3f u = p.unitOrthogonal(), w = p.cross(u);
    mesh.positions[v] = (p + step * (jitter.x() * u + jitter.y() * w)).normalized();
  }
  mesh.computeNormals();
  return mesh;
}

// The square [0, size]^2 in the z = 0 plane as an n x n grid of split quads ((n + 1)^2
// vertices), counter-clockwise seen from +z: an open mesh with one border loop.
inline Mesh squareGrid(int n, float size = 1.0f) {
  Mesh mesh;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) mesh.positions.emplace_back(size * float(x) / float(n), size * float(y) / float(n), 0);
  auto vertex = [n](int x, int y) { return y * (n + 1) + x; };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      mesh.triangles.emplace_back(vertex(x, y), vertex(x + 1, y), vertex(x + 1, y + 1));
      mesh.triangles.emplace_back(vertex(x, y), vertex(x + 1, y + 1), vertex(x, y + 1));
    }
  mesh.computeNormals();
  return mesh;
}

// A CGAL demo mesh ("cow.off"), if installed.
inline std::optional<Mesh> demoMesh(const std::string& name) {
  const std::optional<std::string> path = cgalMesh(name);
  if (!path) return std::nullopt;
  return readMesh(*path);
}

}  // namespace texsynth::test
