#include "texsynth/geometry/cotangent_weights.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace texsynth {

std::vector<CotangentEdge> cotangentEdges(const Mesh& mesh, double maxCotangent) {
  using Vec3d = Eigen::Vector3d;
  const std::size_t n = mesh.vertexCount();
  // Half-edges bucketed by their smaller vertex (a counting sort), then sorted per bucket.
  std::vector<std::int64_t> start(n + 1, 0);
  for (const Vec3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++start[std::size_t(std::min(t[k], t[(k + 1) % 3])) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::pair<std::int32_t, double>> halfEdges(static_cast<std::size_t>(start[n]));
  std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
  for (const Vec3i& t : mesh.triangles) {
    const Vec3d p[3] = {mesh.positions[std::size_t(t[0])].cast<double>(),
                        mesh.positions[std::size_t(t[1])].cast<double>(),
                        mesh.positions[std::size_t(t[2])].cast<double>()};
    for (int k = 0; k < 3; ++k) {
      // Edge (k, k+1); the corner opposite it is k+2.
      const Vec3d u = p[k] - p[(k + 2) % 3], w = p[(k + 1) % 3] - p[(k + 2) % 3];
      const double sine = u.cross(w).norm(), cosine = u.dot(w);
      const double cot = sine > 0 ? std::clamp(cosine / sine, -maxCotangent, maxCotangent)
                                  : (cosine >= 0 ? maxCotangent : -maxCotangent);
      const int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      if (a != b) halfEdges[std::size_t(fill[std::size_t(a)]++)] = {b, 0.5 * cot};
    }
  }
  std::vector<CotangentEdge> edges;
  edges.reserve(halfEdges.size() / 2 + 1);
  for (std::size_t a = 0; a < n; ++a) {
    const auto first = halfEdges.begin() + start[a], last = halfEdges.begin() + fill[a];
    std::sort(first, last, [](const auto& x, const auto& y) { return x.first < y.first; });
    for (auto it = first; it != last;) {
      const std::int32_t b = it->first;
      double weight = 0;
      for (; it != last && it->first == b; ++it) weight += it->second;
      edges.push_back({std::int32_t(a), b, weight});
    }
  }
  return edges;
}

}  // namespace texsynth
