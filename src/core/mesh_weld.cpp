#include "texsynth/core/mesh_weld.h"

#include <algorithm>
#include <numeric>

namespace texsynth {

WeldedMesh weldCoincidentVertices(const Mesh& mesh) {
  const std::size_t n = mesh.vertexCount();
  // Sort by position (ties by index) so that equal positions are adjacent: deterministic, no hashing of floats.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const Vec3f &p = mesh.positions[std::size_t(a)], &q = mesh.positions[std::size_t(b)];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> first(n);  // per vertex: the lowest index at its position
  for (std::size_t i = 0; i < n; ++i) {
    const int v = order[i];
    const bool same = i > 0 && mesh.positions[std::size_t(order[i - 1])] == mesh.positions[std::size_t(v)];
    first[std::size_t(v)] = same ? first[std::size_t(order[i - 1])] : v;
  }
  WeldedMesh out;
  out.vertexOf.assign(n, -1);
  std::vector<int> kept;
  for (std::size_t v = 0; v < n; ++v) {
    if (first[v] == int(v)) {
      out.vertexOf[v] = int(kept.size());
      kept.push_back(int(v));
    }
  }
  if (kept.size() == n) {
    out.mesh = mesh;
    return out;
  }
  for (std::size_t v = 0; v < n; ++v) out.vertexOf[v] = out.vertexOf[std::size_t(first[v])];
  Mesh& welded = out.mesh;
  for (int v : kept) {
    welded.positions.push_back(mesh.positions[std::size_t(v)]);
    if (!mesh.colors.empty()) welded.colors.push_back(mesh.colors[std::size_t(v)]);
  }
  for (const Vec3i& t : mesh.triangles) {
    const Vec3i w(out.vertexOf[std::size_t(t[0])], out.vertexOf[std::size_t(t[1])], out.vertexOf[std::size_t(t[2])]);
    if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) welded.triangles.push_back(w);
  }
  welded.computeNormals();
  return out;
}

}  // namespace texsynth
