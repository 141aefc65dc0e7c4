// The mesh side of surface synthesis: per hierarchy level its topology, smoothed geometry, tangent
// field and the resampled neighborhoods of each size.
#include <chrono>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/timing.h"
#include "texsynth/exemplar/neighborhood.h"
#include "texsynth/geometry/mesh_smoothing.h"
#include "texsynth/image/discrete_steps.h"
#include "texsynth/surface/surface_synthesis.h"

namespace texsynth {

PreparedSurface prepareSurface(MeshHierarchy hierarchy, const SurfaceOrientation& orientation,
                               std::span<const int> neighborhoodSizes, Progress& progress) {
  if (neighborhoodSizes.empty()) throw ParameterError("neighborhood", "needs at least one size");
  for (int n : neighborhoodSizes)
    if (n < 3 || n % 2 == 0 || n > kMaxNeighborhoodSize)
      throw ParameterError("neighborhood", "sizes must be odd and in 3.." + std::to_string(kMaxNeighborhoodSize) +
                                               ", got " + std::to_string(n));
  if (hierarchy.levels.empty()) throw ParameterError("hierarchy", "has no levels");
  const auto start = std::chrono::steady_clock::now();
  PreparedSurface prepared;
  prepared.neighborhoodSizes.assign(neighborhoodSizes.begin(), neighborhoodSizes.end());
  progress.begin("orient and resample the surface", std::int64_t(hierarchy.levels.size()));
  for (std::size_t l = 0; l < hierarchy.levels.size(); ++l) {
    const MeshLevel& level = hierarchy.levels[l];
    PreparedSurfaceLevel preparedLevel{MeshTopology(level.mesh, "mesh level " + std::to_string(l + 1)), {}, {}, {}, {}};
    preparedLevel.geometry = taubinSmoothed(level.mesh, preparedLevel.topology, orientation.geometrySmoothing);
    const Mesh& geometry = preparedLevel.geometry;
    // The field gives the exemplar's up direction b; the neighborhoods' x axis is t = b x n, so
    // that b = n x t as surface_neighborhoods.h lays cells out (exemplar rows across the field).
    preparedLevel.tangents = orientation.field
                                 ? tangentFieldFromRotations(geometry, *orientation.field, orientation.smooth)
                                 : smoothTangentField(geometry, orientation.smooth);
    for (std::size_t v = 0; v < preparedLevel.tangents.size(); ++v)
      preparedLevel.tangents[v] = preparedLevel.tangents[v].cross(geometry.normals[v]).normalized();
    for (int n : neighborhoodSizes) {
      const std::vector<std::int32_t> centres = selectActiveCentres(geometry, level.spacing, detail::activeStride(n));
      preparedLevel.neighborhoods.push_back(
          resampleNeighborhoods(geometry, preparedLevel.topology, preparedLevel.tangents, level.spacing, n, centres));
    }
    preparedLevel.stencil =
        buildSurfaceStencil(geometry, preparedLevel.topology, preparedLevel.tangents, level.spacing, kStencilSize);
    prepared.levels.push_back(std::move(preparedLevel));
    progress.advance(1);
  }
  progress.end();
  prepared.hierarchy = std::move(hierarchy);
  prepared.seconds = secondsSince(start);
  return prepared;
}

}  // namespace texsynth
