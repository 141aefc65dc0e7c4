// Midpoint subdivision: four triangles per triangle, one shared vertex per edge.
#include "texsynth/geometry/mesh_subdivision.h"

#include <unordered_map>

namespace texsynth {

namespace {

std::uint64_t edgeKey(int a, int b) {
  const auto lo = std::uint64_t(std::min(a, b)), hi = std::uint64_t(std::max(a, b));
  return lo << 32 | hi;
}

}  // namespace

Mesh subdivideMidpoint(const Mesh& mesh) {
  mesh.validate("mesh");
  Mesh out;
  out.positions = mesh.positions;
  out.normals = mesh.normals;
  out.colors = mesh.colors;
  out.triangles.reserve(mesh.triangles.size() * 4);
  std::unordered_map<std::uint64_t, int> midpoints;
  midpoints.reserve(mesh.triangles.size() * 2);
  const auto midpoint = [&](int a, int b) {
    const auto [it, added] = midpoints.try_emplace(edgeKey(a, b), int(out.positions.size()));
    if (!added) return it->second;
    const std::size_t i = std::size_t(a), j = std::size_t(b);
    out.positions.push_back(0.5f * (mesh.positions[i] + mesh.positions[j]));
    if (!mesh.normals.empty()) {
      const Vec3f n = mesh.normals[i] + mesh.normals[j];
      out.normals.push_back(n.squaredNorm() > 0 ? Vec3f(n.normalized()) : mesh.normals[i]);
    }
    if (!mesh.colors.empty()) out.colors.push_back(0.5f * (mesh.colors[i] + mesh.colors[j]));
    return it->second;
  };
  for (const Vec3i& t : mesh.triangles) {
    const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

Mesh subdivideToVertices(const Mesh& mesh, std::size_t minVertices, std::size_t maxVertices) {
  Mesh out = mesh;
  // A level adds one vertex per edge: about three times the vertices of a closed triangle mesh.
  while (out.vertexCount() < minVertices && out.vertexCount() + out.triangleCount() * 3 / 2 <= maxVertices)
    out = subdivideMidpoint(out);
  return out;
}

}  // namespace texsynth
