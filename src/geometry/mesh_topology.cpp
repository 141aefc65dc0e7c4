#include "texsynth/geometry/mesh_topology.h"

#include <algorithm>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

std::string edgeName(int a, int b) {
  return "between vertices " + std::to_string(std::min(a, b)) + " and " + std::to_string(std::max(a, b));
}

// Throws for the first face (by index) that repeats a vertex or spans no area.
void checkFaces(const Mesh& mesh, const std::string& source) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3i& f = mesh.triangles[t];
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0])
      throw InputError(source, "face " + std::to_string(t) + " is degenerate (it repeats a vertex)");
    if (faceHasZeroArea(mesh.positions, f))
      throw InputError(source, "face " + std::to_string(t) + " is degenerate (zero area)");
  }
}

// What the faces around one half-edge look like.
struct EdgeFaces {
  int others = 0;          // faces besides this one that use the edge
  int opposite = -1;       // 3 * face + edge of a face traversing it the other way
  int sameDirection = -1;  // a face traversing it the same way (inconsistent orientation)
};

}  // namespace

MeshTopology::MeshTopology(const Mesh& mesh, const std::string& source) {
  mesh.validate(source);
  checkFaces(mesh, source);
  triangles_ = mesh.triangles;
  const int vertices = int(mesh.positions.size()), faces = int(triangles_.size());

  // Faces around each vertex in ascending order (counting sort), the order fans are found in.
  ringOffsets_.assign(std::size_t(vertices) + 1, 0);
  for (const Vec3i& f : triangles_)
    for (int k = 0; k < 3; ++k) ++ringOffsets_[std::size_t(f[k]) + 1];
  for (int v = 0; v < vertices; ++v) ringOffsets_[std::size_t(v) + 1] += ringOffsets_[std::size_t(v)];
  std::vector<int> incident(std::size_t(3) * std::size_t(faces));
  {
    std::vector<int> fill(ringOffsets_.begin(), ringOffsets_.end() - 1);
    for (int t = 0; t < faces; ++t)
      for (int k = 0; k < 3; ++k) incident[std::size_t(fill[std::size_t(triangles_[std::size_t(t)][k])]++)] = t;
  }

  // Each half-edge a -> b looks for the other faces at a that also use b.
  std::vector<EdgeFaces> edges(std::size_t(3) * std::size_t(faces));
  parallelFor(
      0, faces,
      [&](std::int64_t t) {
        const Vec3i& f = triangles_[std::size_t(t)];
        for (int e = 0; e < 3; ++e) {
          const int a = f[e], b = f[(e + 1) % 3];
          EdgeFaces& out = edges[std::size_t(3 * t + e)];
          for (int i = ringOffsets_[std::size_t(a)]; i < ringOffsets_[std::size_t(a) + 1]; ++i) {
            const int u = incident[std::size_t(i)];
            if (u == t) continue;
            const Vec3i& g = triangles_[std::size_t(u)];
            for (int k = 0; k < 3; ++k) {
              if (g[k] == b && g[(k + 1) % 3] == a) {
                ++out.others;
                if (out.opposite < 0) out.opposite = 3 * u + k;
              } else if (g[k] == a && g[(k + 1) % 3] == b) {
                ++out.others;
                if (out.sameDirection < 0) out.sameDirection = u;
              }
            }
          }
        }
      },
      256);

  // The first problem in face order, then the neighbours and borders.
  neighbors_.assign(edges.size(), -1);
  neighborEdges_.assign(edges.size(), -1);
  border_.assign(std::size_t(vertices), 0);
  for (int t = 0; t < faces; ++t)
    for (int e = 0; e < 3; ++e) {
      const EdgeFaces& edge = edges[std::size_t(3 * t + e)];
      const int a = triangles_[std::size_t(t)][e], b = triangles_[std::size_t(t)][(e + 1) % 3];
      if (edge.others > 1)
        throw InputError(source,
                         "non-manifold edge " + edgeName(a, b) + " (" + std::to_string(edge.others + 1) + " faces)");
      if (edge.sameDirection >= 0)
        throw InputError(source, "faces " + std::to_string(t) + " and " + std::to_string(edge.sameDirection) +
                                     " traverse the edge " + edgeName(a, b) +
                                     " in the same direction (inconsistent orientation)");
      if (edge.opposite >= 0) {
        neighbors_[std::size_t(3 * t + e)] = edge.opposite / 3;
        neighborEdges_[std::size_t(3 * t + e)] = static_cast<signed char>(edge.opposite % 3);
      } else {
        ++borderEdges_;
        border_[std::size_t(a)] = border_[std::size_t(b)] = 1;
      }
    }

  // Fans: from the lowest unvisited face, back (clockwise) to a border or all the way round,
  // then forward (counter-clockwise) across each face's edge entering the vertex.
  ring_.assign(incident.size(), -1);
  std::vector<unsigned char> fanStart(incident.size(), 0);
  parallelFor(
      0, vertices,
      [&](std::int64_t v) {
        const int begin = ringOffsets_[std::size_t(v)], end = ringOffsets_[std::size_t(v) + 1];
        std::vector<unsigned char> visited(std::size_t(end - begin), 0);
        auto slot = [&](int t) {
          return int(std::lower_bound(incident.begin() + begin, incident.begin() + end, t) - incident.begin()) - begin;
        };
        int out = begin;
        for (int seed = 0; seed < end - begin; ++seed) {
          if (visited[std::size_t(seed)]) continue;
          const int first = incident[std::size_t(begin + seed)];
          int start = first;
          for (int steps = 0; steps < end - begin; ++steps) {
            const int back = neighbor(start, cornerOf(start, int(v)));
            if (back < 0) break;
            if (back == first) {  // all the way round: a closed fan starts at its lowest face
              start = first;
              break;
            }
            start = back;
          }
          fanStart[std::size_t(out)] = 1;
          int t = start;
          do {
            visited[std::size_t(slot(t))] = 1;
            ring_[std::size_t(out++)] = t;
            t = neighbor(t, (cornerOf(t, int(v)) + 2) % 3);
          } while (t >= 0 && t != start && out < end);
        }
      },
      256);
  fanOffsets_.assign(std::size_t(vertices) + 1, 0);
  for (int v = 0; v < vertices; ++v) {
    fanOffsets_[std::size_t(v) + 1] = fanOffsets_[std::size_t(v)];
    for (int i = ringOffsets_[std::size_t(v)]; i < ringOffsets_[std::size_t(v) + 1]; ++i)
      if (fanStart[std::size_t(i)]) {
        fanStarts_.push_back(i);
        ++fanOffsets_[std::size_t(v) + 1];
      }
  }
}

int MeshTopology::cornerOf(int t, int v) const {
  const Vec3i& f = triangles_[std::size_t(t)];
  return f[0] == v ? 0 : f[1] == v ? 1 : f[2] == v ? 2 : -1;
}

std::span<const int> MeshTopology::trianglesAround(int v) const {
  const int begin = ringOffsets_[std::size_t(v)], end = ringOffsets_[std::size_t(v) + 1];
  return {ring_.data() + begin, std::size_t(end - begin)};
}

std::span<const int> MeshTopology::fan(int v, int k) const {
  const int index = fanOffsets_[std::size_t(v)] + k;
  const int begin = fanStarts_[std::size_t(index)];
  const int end = k + 1 < fanCount(v) ? fanStarts_[std::size_t(index) + 1] : ringOffsets_[std::size_t(v) + 1];
  return {ring_.data() + begin, std::size_t(end - begin)};
}

bool faceHasZeroArea(const std::vector<Vec3f>& positions, const Vec3i& face) {
  const Eigen::Vector3d a = positions[std::size_t(face[0])].cast<double>();
  const Eigen::Vector3d ab = positions[std::size_t(face[1])].cast<double>() - a;
  const Eigen::Vector3d ac = positions[std::size_t(face[2])].cast<double>() - a;
  return ab.cross(ac).squaredNorm() == 0;
}

}  // namespace texsynth
