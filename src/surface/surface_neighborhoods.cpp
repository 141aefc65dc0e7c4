// Resampled surface neighbourhoods, x_p = W_p x (surface_neighborhoods.h): parameter checks, the
// renumbered mesh, the parallel loop over centres (neighborhood_unfolding.cpp walks each) and the
// member / covering lists.
#include "texsynth/surface/surface_neighborhoods.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "neighborhood_unfolding.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {

namespace surface_detail {

WalkMesh::WalkMesh(const Mesh& mesh, const MeshTopology& topology) {
  const std::size_t triangles = std::size_t(topology.triangleCount()), vertices = mesh.vertexCount();
  const Box3f box = mesh.bounds();
  const Vec3f scale = Vec3f::Constant(65535.0f).cwiseQuotient(box.size().cwiseMax(Vec3f::Constant(1e-30f)));
  std::vector<std::pair<std::uint64_t, std::int32_t>> order(triangles);
  parallelFor(
      0, std::int64_t(triangles),
      [&](std::int64_t t) {
        const Vec3i& c = topology.triangles()[std::size_t(t)];
        Vec3f centroid = (mesh.positions[std::size_t(c[0])] + mesh.positions[std::size_t(c[1])] +
                          mesh.positions[std::size_t(c[2])]) /
                         3.0f;
        Vec3f q = (centroid - box.min).cwiseProduct(scale).cwiseMax(Vec3f::Zero()).cwiseMin(Vec3f::Constant(65535));
        std::uint64_t code = 0;
        for (int bit = 15; bit >= 0; --bit)
          for (int axis = 0; axis < 3; ++axis) code = code << 1 | ((std::uint32_t(q[axis]) >> bit) & 1u);
        order[std::size_t(t)] = {code, std::int32_t(t)};
      },
      4096);
  std::sort(order.begin(), order.end());
  triangleRank.resize(triangles);
  vertexRank.assign(vertices, -1);
  vertexOf.clear();
  for (std::size_t i = 0; i < triangles; ++i) {
    triangleRank[std::size_t(order[i].second)] = std::int32_t(i);
    for (int c : topology.triangles()[std::size_t(order[i].second)]) {
      if (vertexRank[std::size_t(c)] >= 0) continue;
      vertexRank[std::size_t(c)] = std::int32_t(vertexOf.size());
      vertexOf.push_back(c);
    }
  }
  for (std::size_t v = 0; v < vertices; ++v) {  // vertices no face uses
    if (vertexRank[v] >= 0) continue;
    vertexRank[v] = std::int32_t(vertexOf.size());
    vertexOf.push_back(std::int32_t(v));
  }
  records.resize(triangles);
  parallelFor(
      0, std::int64_t(triangles),
      [&](std::int64_t i) {
        const int t = order[std::size_t(i)].second;
        const Vec3i& corners = topology.triangles()[std::size_t(t)];
        TriangleRecord& r = records[std::size_t(i)];
        for (int e = 0; e < 3; ++e) {
          r.v[std::size_t(e)] = vertexRank[std::size_t(corners[e])];
          int n = topology.neighbor(t, e);
          r.across[std::size_t(e)] = n < 0 ? -1 : 4 * triangleRank[std::size_t(n)] + topology.neighborEdge(t, e);
          const Vec3f& a = mesh.positions[std::size_t(corners[e])];
          Vec3f edge = mesh.positions[std::size_t(corners[(e + 1) % 3])] - a;
          Vec3f third = mesh.positions[std::size_t(corners[(e + 2) % 3])] - a;
          float length2 = edge.squaredNorm();  // > 0: MeshTopology rejects degenerate faces
          r.along[std::size_t(e)] = edge.dot(third) / length2;
          r.out[std::size_t(e)] = edge.cross(third).norm() / length2;
        }
      },
      4096);
}

}  // namespace surface_detail

namespace {

// Centres per task: enough work per task, and the chunk buffers stay few.
constexpr std::int64_t kCentresPerChunk = 16;

}  // namespace

void SurfaceNeighborhoods::resample(std::size_t a, std::span<const float> values, int channels,
                                    std::span<float> out) const {
  TS_CHECK(channels > 0 && out.size() >= std::size_t(cellCount() * channels) &&
           values.size() >= vertexCount() * std::size_t(channels));
  std::span<const NeighborhoodCell> row = cellsOf(a);
  for (std::size_t c = 0; c < row.size(); ++c) {
    for (int k = 0; k < channels; ++k) {
      float sum = 0;
      for (int j = 0; j < 3; ++j)
        sum += row[c].weight[j] * values[std::size_t(row[c].vertex[j]) * std::size_t(channels) + std::size_t(k)];
      out[c * std::size_t(channels) + std::size_t(k)] = sum;
    }
  }
}

SurfaceNeighborhoods resampleNeighborhoods(const Mesh& mesh, const MeshTopology& topology,
                                           std::span<const Vec3f> tangents, float spacing, int size,
                                           std::span<const std::int32_t> centres) {
  if (!(spacing > 0) || !std::isfinite(spacing))
    throw ParameterError("spacing", "must be positive and finite, got " + std::to_string(spacing));
  if (size < 1 || size % 2 == 0)
    throw ParameterError("size", "must be a positive odd number of cells, got " + std::to_string(size));
  const std::size_t vertexCount = mesh.vertexCount();
  if (mesh.normals.size() != vertexCount)
    throw ParameterError("mesh", "needs one normal per vertex (" + std::to_string(mesh.normals.size()) + " for " +
                                     std::to_string(vertexCount) + " vertices)");
  if (tangents.size() != vertexCount)
    throw ParameterError("tangents", "needs one per vertex (" + std::to_string(tangents.size()) + " for " +
                                         std::to_string(vertexCount) + " vertices)");
  if (topology.vertexCount() != int(vertexCount) || topology.triangleCount() != int(mesh.triangleCount()))
    throw ParameterError("topology", "was built from another mesh");
  for (std::int32_t c : centres)
    if (c < 0 || std::size_t(c) >= vertexCount)
      throw ParameterError("centres", "vertex " + std::to_string(c) + " is not in the mesh");

  SurfaceNeighborhoods result;
  result.size = size;
  result.radius = size / 2;
  result.spacing = spacing;
  result.centres.assign(centres.begin(), centres.end());
  const std::size_t cellCount = std::size_t(size) * std::size_t(size), active = centres.size();
  result.cells.resize(active * cellCount);

  const surface_detail::WalkMesh walk(mesh, topology);
  const surface_detail::NeighborhoodUnfolder walker(mesh, topology, walk, tangents, spacing, size);
  // Centres are walked in the renumbered (spatial) order, so that consecutive walks of a task
  // reuse what the previous ones brought into the cache; each task keeps its members in a buffer
  // of its own, copied to their places afterwards.
  std::vector<std::int32_t> order(active);
  for (std::size_t a = 0; a < active; ++a) order[a] = std::int32_t(a);
  std::sort(order.begin(), order.end(), [&](std::int32_t l, std::int32_t r) {
    const std::int32_t rl = walk.vertexRank[std::size_t(centres[std::size_t(l)])];
    const std::int32_t rr = walk.vertexRank[std::size_t(centres[std::size_t(r)])];
    return rl != rr ? rl < rr : l < r;
  });
  const std::int64_t chunks = (std::int64_t(active) + kCentresPerChunk - 1) / kCentresPerChunk;
  std::vector<std::vector<NeighborhoodMember>> chunkMembers(static_cast<std::size_t>(chunks));
  std::vector<std::int64_t> counts(active + 1, 0), offsetInChunk(active, 0);
  parallelFor(0, chunks, [&](std::int64_t chunk) {
    std::vector<NeighborhoodMember>& members = chunkMembers[std::size_t(chunk)];
    members.reserve(std::size_t(kCentresPerChunk) * cellCount * 5 / 4);  // about one vertex per cell
    const std::size_t end = std::min(active, std::size_t(chunk + 1) * kCentresPerChunk);
    for (std::size_t i = std::size_t(chunk) * kCentresPerChunk; i < end; ++i) {
      const std::size_t a = std::size_t(order[i]);
      offsetInChunk[a] = std::int64_t(members.size());
      walker.run(centres[a], std::span(result.cells).subspan(a * cellCount, cellCount), members);
      counts[a + 1] = std::int64_t(members.size()) - offsetInChunk[a];
    }
  });

  result.memberStart.assign(active + 1, 0);
  for (std::size_t a = 0; a < active; ++a) result.memberStart[a + 1] = result.memberStart[a] + counts[a + 1];
  result.members.resize(std::size_t(result.memberStart[active]));
  parallelFor(0, chunks, [&](std::int64_t chunk) {
    const auto& part = chunkMembers[std::size_t(chunk)];
    const std::size_t end = std::min(active, std::size_t(chunk + 1) * kCentresPerChunk);
    for (std::size_t i = std::size_t(chunk) * kCentresPerChunk; i < end; ++i) {
      const std::size_t a = std::size_t(order[i]);
      std::copy_n(part.begin() + offsetInChunk[a], counts[a + 1], result.members.begin() + result.memberStart[a]);
    }
  });

  result.coveringStart.assign(vertexCount + 1, 0);
  for (const NeighborhoodMember& m : result.members) ++result.coveringStart[std::size_t(m.vertex) + 1];
  for (std::size_t v = 0; v < vertexCount; ++v) result.coveringStart[v + 1] += result.coveringStart[v];
  result.covering.resize(result.members.size());
  std::vector<std::int64_t> cursor(result.coveringStart.begin(), result.coveringStart.end() - 1);
  for (std::size_t a = 0; a < active; ++a)
    for (const NeighborhoodMember& m : result.membersOf(a))
      result.covering[std::size_t(cursor[std::size_t(m.vertex)]++)] = {std::int32_t(a), m.dx, m.dy};
  return result;
}

}  // namespace texsynth
