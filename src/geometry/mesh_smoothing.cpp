// Taubin smoothing (mesh_smoothing.h): Jacobi steps with weights and directions fixed from the
// input mesh, so the filter is linear (Taubin's pass-band analysis holds) and each pass reads only
// the previous one (the result does not depend on the thread count).
#include "texsynth/geometry/mesh_smoothing.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/geometry/cotangent_weights.h"

namespace texsynth {

namespace {

constexpr float kLambda = 0.5f, kMu = -0.53f;  // Taubin's pass band: mu < -lambda < 0
// Cotangent weights are clamped to this share of a vertex's largest, so that an obtuse
// triangle's negative weight cannot push a vertex away from its neighbours.
constexpr double kWeightFloor = 0.05;

// Cotangents are clamped to this magnitude (a near-degenerate triangle), as the tangent field's.
constexpr double kMaxCotangent = 1e3;

// Per vertex its distinct edge neighbours (CSR, in ascending order) with their
// normalized cotangent weights: the weighted mean of the neighbours lies in the tangent plane on
// a flat region and along the normal on a sphere, however irregular the triangles.
struct CotangentNeighbours {
  std::vector<std::int32_t> offsets, vertices;
  std::vector<float> weights;

  explicit CotangentNeighbours(const Mesh& mesh) {
    const std::size_t n = mesh.vertexCount();
    const std::vector<CotangentEdge> edges = cotangentEdges(mesh, kMaxCotangent);
    offsets.assign(n + 1, 0);
    for (const CotangentEdge& e : edges) ++offsets[std::size_t(e.a) + 1], ++offsets[std::size_t(e.b) + 1];
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    // Edges come in ascending (a, b) order: each vertex receives its smaller neighbours first,
    // then its larger ones, both ascending.
    std::vector<double> raw(std::size_t(offsets.back()));
    vertices.resize(raw.size());
    std::vector<std::int32_t> fill(offsets.begin(), offsets.end() - 1);
    for (const CotangentEdge& e : edges) {
      const auto i = std::size_t(fill[std::size_t(e.a)]++), j = std::size_t(fill[std::size_t(e.b)]++);
      vertices[i] = e.b, raw[i] = e.weight;
      vertices[j] = e.a, raw[j] = e.weight;
    }
    weights.resize(raw.size());
    parallelForChunks(0, std::int64_t(n), 4096, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t v = begin; v < end; ++v) {
        const auto first = std::size_t(offsets[std::size_t(v)]), last = std::size_t(offsets[std::size_t(v) + 1]);
        if (first == last) continue;
        const double largest =
            *std::max_element(raw.begin() + std::ptrdiff_t(first), raw.begin() + std::ptrdiff_t(last));
        double sum = 0;
        for (std::size_t i = first; i < last; ++i) sum += raw[i] = std::max(raw[i], kWeightFloor * largest);
        for (std::size_t i = first; i < last; ++i)
          weights[i] = float(sum > 0 ? raw[i] / sum : 1.0 / double(last - first));
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
  const CotangentNeighbours neighbours(mesh);
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
