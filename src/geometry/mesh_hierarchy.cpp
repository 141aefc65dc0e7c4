#include "texsynth/geometry/mesh_hierarchy.h"

#include <chrono>
#include <cmath>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/timing.h"
#include "texsynth/geometry/mesh_retiling.h"
#include "texsynth/geometry/mesh_topology.h"
#include "texsynth/geometry/surface_projector.h"

namespace texsynth {
namespace {

constexpr int kMinimumLevelVertices = 32;

void findParents(MeshLevel& level, const Mesh& coarser) {
  const SurfaceProjector projector(coarser);
  const std::size_t count = level.mesh.positions.size();
  level.parentTriangle.assign(count, -1);
  level.parentBarycentric.assign(count, Vec3f(1, 0, 0));
  parallelFor(
      0, std::int64_t(count),
      [&](std::int64_t v) {
        const SurfacePoint closest = projector.closestPoint(level.mesh.positions[std::size_t(v)]);
        level.parentTriangle[std::size_t(v)] = closest.triangle;
        level.parentBarycentric[std::size_t(v)] = closest.barycentric;
      },
      512);
}

}  // namespace

int minimumFinestVertices(int levels, float ratio) {
  // lround(vertices / ratio^(levels - 1)) >= 32 once that quotient reaches 31.5.
  return int(std::ceil((kMinimumLevelVertices - 0.5) * std::pow(double(ratio), levels - 1)));
}

std::vector<int> meshLevelVertexCounts(const MeshHierarchyOptions& options) {
  if (options.vertices < 1 || options.vertices > 50'000'000)
    throw ParameterError("vertices", "must be in [1, 50000000], got " + std::to_string(options.vertices));
  if (options.levels < 1 || options.levels > 16)
    throw ParameterError("levels", "must be in [1, 16], got " + std::to_string(options.levels));
  if (!(options.ratio > 1.0f && options.ratio <= 64.0f))
    throw ParameterError("ratio", "must be in (1, 64], got " + std::to_string(options.ratio));
  std::vector<int> counts(std::size_t(options.levels));
  for (int l = 0; l < options.levels; ++l)
    counts[std::size_t(l)] =
        int(std::lround(double(options.vertices) / std::pow(double(options.ratio), options.levels - 1 - l)));
  if (options.vertices < minimumFinestVertices(options.levels, options.ratio))
    throw ParameterError("levels", "the coarsest of " + std::to_string(options.levels) + " levels would get " +
                                       std::to_string(counts[0]) +
                                       " vertices (vertices / ratio^(levels - 1)); at least " +
                                       std::to_string(kMinimumLevelVertices) + " are needed");
  return counts;
}

MeshHierarchy buildMeshHierarchy(const Mesh& input, const MeshHierarchyOptions& options, const std::string& source,
                                 Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<int> counts = meshLevelVertexCounts(options);
  const MeshTopology check(input, source);  // one clear InputError before any level starts
  MeshHierarchy hierarchy;
  hierarchy.levels.resize(counts.size());

  // Levels are independent retilings (CGAL is single-threaded): run them side by side.
  progress.begin("retiling", std::int64_t(counts.size()));
  parallelFor(0, std::int64_t(counts.size()), [&](std::int64_t l) {
    RetileOptions retile;
    retile.targetVertices = counts[std::size_t(l)];
    MeshLevel& level = hierarchy.levels[std::size_t(l)];
    level.mesh = retileMesh(input, retile, source);
    level.spacing = float(std::sqrt(level.mesh.surfaceArea() / double(level.mesh.positions.size())));
    progress.advance();
  });
  progress.end();

  progress.begin("parent triangles", std::int64_t(counts.size()) - 1);
  for (std::size_t l = 1; l < counts.size(); ++l) {
    findParents(hierarchy.levels[l], hierarchy.levels[l - 1].mesh);
    progress.advance();
  }
  progress.end();
  hierarchy.seconds = secondsSince(start);
  return hierarchy;
}

}  // namespace texsynth
