// Taubin smoothing (mesh_smoothing.h): Jacobi steps with weights and directions fixed from the
// input mesh, so the filter is linear (Taubin's pass-band analysis holds) and each pass reads only
// the previous one (the result does not depend on the thread count).
#include "texsynth/geometry/mesh_smoothing.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {

namespace {

constexpr float kLambda = 0.5f, kMu = -0.53f;  // Taubin's pass band: mu < -lambda < 0
// Cotangent weights are clamped to this share of a vertex's largest, so that an obtuse
// triangle's negative weight cannot push a vertex away from its neighbours.
constexpr float kWeightFloor = 0.05f;

float cotangent(const Vec3f& a, const Vec3f& b) {
  const float sine = a.cross(b).norm();
  return sine > 0 ? a.dot(b) / sine : 0.0f;
}

// Per vertex its distinct edge neighbours (CSR, in ascending order) with their
// normalized cotangent weights: the weighted mean of the neighbours lies in the tangent plane on
// a flat region and along the normal on a sphere, however irregular the triangles. Built per
// vertex from its own triangles, in parallel.
struct CotangentNeighbours {
  std::vector<std::int32_t> offsets, vertices;
  std::vector<float> weights;

  CotangentNeighbours(const Mesh& mesh, const MeshTopology& topology) {
    const std::int64_t n = topology.vertexCount();
    // Vertex v's neighbours and weights, appended to the given lists (which it clears).
    auto collect = [&](std::int64_t v, std::vector<std::int32_t>& around, std::vector<float>& w) {
      thread_local std::vector<std::pair<std::int32_t, float>> order;
      around.clear();
      w.clear();
      for (int t : topology.trianglesAround(int(v))) {
        const Vec3i& tri = topology.triangles()[std::size_t(t)];
        const int corner = topology.cornerOf(t, int(v));
        const Vec3f& p = mesh.positions[std::size_t(v)];
        for (int k = 1; k <= 2; ++k) {
          // The edge from v to corner + k; its weight is half the cotangent at the third corner.
          const std::int32_t b = tri[(corner + k) % 3], c = tri[(corner + 3 - k) % 3];
          const Vec3f& pc = mesh.positions[std::size_t(c)];
          const float weight = 0.5f * cotangent(p - pc, mesh.positions[std::size_t(b)] - pc);
          const auto found = std::find(around.begin(), around.end(), b);
          if (found == around.end()) {
            around.push_back(b);
            w.push_back(weight);
          } else {
            w[std::size_t(found - around.begin())] += weight;
          }
        }
      }
      if (around.empty()) return;
      // In ascending vertex order, so that the sums below do not depend on the triangles' order.
      order.resize(around.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = {around[i], w[i]};
      std::sort(order.begin(), order.end());
      for (std::size_t i = 0; i < order.size(); ++i) around[i] = order[i].first, w[i] = order[i].second;
      const float largest = *std::max_element(w.begin(), w.end());
      float sum = 0;
      for (float& x : w) sum += x = std::max(x, kWeightFloor * largest);
      for (float& x : w) x = sum > 0 ? x / sum : 1.0f / float(w.size());
    };
    offsets.assign(std::size_t(n) + 1, 0);
    parallelForChunks(0, n, 4096, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::int32_t> around;
      std::vector<float> w;
      for (std::int64_t v = begin; v < end; ++v) {
        collect(v, around, w);
        offsets[std::size_t(v) + 1] = std::int32_t(around.size());
      }
    });
    for (std::size_t v = 0; v < std::size_t(n); ++v) offsets[v + 1] += offsets[v];
    vertices.resize(std::size_t(offsets.back()));
    weights.resize(vertices.size());
    parallelForChunks(0, n, 4096, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::int32_t> around;
      std::vector<float> w;
      for (std::int64_t v = begin; v < end; ++v) {
        collect(v, around, w);
        std::copy(around.begin(), around.end(), vertices.begin() + offsets[std::size_t(v)]);
        std::copy(w.begin(), w.end(), weights.begin() + offsets[std::size_t(v)]);
      }
    });
  }
};

}  // namespace

Mesh taubinSmoothed(const Mesh& mesh, const MeshTopology& topology, int iterations) {
  if (iterations < 0) throw ParameterError("iterations", "must be >= 0, got " + std::to_string(iterations));
  Mesh smoothed = mesh;
  if (iterations == 0) return smoothed;
  if (smoothed.normals.size() != smoothed.vertexCount()) smoothed.computeNormals();
  const std::vector<Vec3f> normals = smoothed.normals;
  const CotangentNeighbours neighbours(mesh, topology);
  std::vector<Vec3f> next(mesh.positions.size());
  auto step = [&](float factor) {
    const std::vector<Vec3f>& current = smoothed.positions;
    parallelForChunks(0, std::int64_t(current.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t v = begin; v < end; ++v) {
        const auto first = std::size_t(neighbours.offsets[std::size_t(v)]),
                   last = std::size_t(neighbours.offsets[std::size_t(v) + 1]);
        const Vec3f& x = current[std::size_t(v)];
        if (first == last || topology.isBorderVertex(int(v))) {
          next[std::size_t(v)] = x;
          continue;
        }
        Vec3f mean = Vec3f::Zero();
        for (std::size_t i = first; i < last; ++i)
          mean += neighbours.weights[i] * current[std::size_t(neighbours.vertices[i])];
        // Along the normal only: the vertices keep their places on the surface, so the texture
        // laid out on the smoothed mesh is not shifted on the output's.
        const Vec3f& n = normals[std::size_t(v)];
        next[std::size_t(v)] = x + factor * (mean - x).dot(n) * n;
      }
    });
    smoothed.positions.swap(next);
  };
  for (int i = 0; i < iterations; ++i) {
    step(kLambda);
    step(kMu);
  }
  smoothed.computeNormals();
  return smoothed;
}

}  // namespace texsynth
