#pragma once
// Small scenes and image measurements shared by the render tests.
#include <cmath>

#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"

namespace texsynth::test {

// Appends a triangle with its own three vertices, all of one colour.
inline void addColoredTriangle(Mesh& mesh, const Vec3f& a, const Vec3f& b, const Vec3f& c, const Vec3f& color) {
  const int base = int(mesh.positions.size());
  for (const Vec3f& p : {a, b, c}) {
    mesh.positions.push_back(p);
    mesh.colors.push_back(color);
  }
  mesh.triangles.emplace_back(base, base + 1, base + 2);
}

// Appends another mesh (keeping its colours, or giving it `color` if it has none).
inline void appendMesh(Mesh& mesh, const Mesh& part, const Vec3f& color) {
  const int base = int(mesh.positions.size());
  for (std::size_t i = 0; i < part.positions.size(); ++i) {
    mesh.positions.push_back(part.positions[i]);
    mesh.colors.push_back(part.colors.empty() ? color : part.colors[i]);
    if (!part.normals.empty()) mesh.normals.push_back(part.normals[i]);
  }
  for (const Vec3i& t : part.triangles) mesh.triangles.push_back(t + Vec3i::Constant(base));
}

inline Vec3f pixelColor(const Image& image, int x, int y) {
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}

inline bool isBackground(const Image& image, int x, int y, const Vec3f& background) {
  return (pixelColor(image, x, y) - background).cwiseAbs().maxCoeff() < 1e-6f;
}

// Mean colour of the pixels that are not background, and how many there are.
struct ForegroundStats {
  Vec3f mean = Vec3f::Zero();
  int count = 0;
};

inline ForegroundStats foreground(const Image& image, const Vec3f& background) {
  ForegroundStats stats;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!isBackground(image, x, y, background)) {
        stats.mean += pixelColor(image, x, y);
        ++stats.count;
      }
  if (stats.count) stats.mean /= float(stats.count);
  return stats;
}

}  // namespace texsynth::test
