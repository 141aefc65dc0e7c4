#include "texsynth/render/primitives.h"

#include <cmath>
#include <numbers>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

Mesh makeBoxMesh(const Vec3f& min, const Vec3f& max) {
  if (!min.allFinite() || !max.allFinite() || !(min.array() < max.array()).all())
    throw ParameterError("box", "needs finite corners with min < max on every axis");
  Mesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    // (u, v, axis) is a right-handed cycle, so corners ordered around (u, v) wind
    // counter-clockwise seen from +axis; the -axis face reverses the order.
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const int base = int(mesh.positions.size());
      const float cornerU[4] = {min[u], max[u], max[u], min[u]}, cornerV[4] = {min[v], min[v], max[v], max[v]};
      for (int k = 0; k < 4; ++k) {
        Vec3f p;
        p[axis] = side ? max[axis] : min[axis];
        p[u] = cornerU[k];
        p[v] = cornerV[k];
        mesh.positions.push_back(p);
        mesh.normals.push_back((side ? 1.0f : -1.0f) * Vec3f::Unit(axis));
      }
      if (side) {
        mesh.triangles.emplace_back(base, base + 1, base + 2);
        mesh.triangles.emplace_back(base, base + 2, base + 3);
      } else {
        mesh.triangles.emplace_back(base, base + 2, base + 1);
        mesh.triangles.emplace_back(base, base + 3, base + 2);
      }
    }
  }
  return mesh;
}

Mesh makeUvSphereMesh(const Vec3f& center, float radius, int rings, int segments) {
  if (!center.allFinite()) throw ParameterError("center", "must be finite");
  if (!(radius > 0 && std::isfinite(radius))) throw ParameterError("radius", "must be finite and > 0");
  if (rings < 2 || rings > 4096) throw ParameterError("rings", "must be in [2, 4096], got " + std::to_string(rings));
  if (segments < 3 || segments > 4096)
    throw ParameterError("segments", "must be in [3, 4096], got " + std::to_string(segments));
  Mesh mesh;
  const float pi = std::numbers::pi_v<float>;
  // (segments + 1) columns: the seam is duplicated so each vertex keeps one longitude.
  for (int r = 0; r <= rings; ++r) {
    const float theta = pi * float(r) / float(rings);  // 0 at the +Y pole
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2 * pi * float(s) / float(segments);
      Vec3f direction(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      mesh.positions.push_back(center + radius * direction);
      mesh.normals.push_back(direction);
    }
  }
  auto vertex = [&](int r, int s) { return r * (segments + 1) + s; };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      // Going down in theta then across in phi turns counter-clockwise seen from outside.
      // The triangle touching a pole along its collapsed edge is skipped.
      if (r != rings - 1) mesh.triangles.emplace_back(vertex(r, s), vertex(r + 1, s), vertex(r + 1, s + 1));
      if (r != 0) mesh.triangles.emplace_back(vertex(r, s), vertex(r + 1, s + 1), vertex(r, s + 1));
    }
  return mesh;
}

}  // namespace texsynth
