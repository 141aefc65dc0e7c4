// Every vertex's flattened neighbourhood (surface_stencil.h), from resampleNeighborhoods with
// every vertex a centre, in batches so that the resampled cells (not kept) stay small.
#include "texsynth/surface/surface_stencil.h"

#include <algorithm>
#include <numeric>

namespace texsynth {

SurfaceStencil buildSurfaceStencil(const Mesh& mesh, const MeshTopology& topology, std::span<const Vec3f> tangents,
                                   float spacing, int size) {
  constexpr std::int32_t kBatch = 32768;
  SurfaceStencil stencil;
  stencil.size = size;
  const auto vertices = std::int32_t(mesh.vertexCount());
  stencil.start.reserve(std::size_t(vertices) + 1);
  stencil.start.push_back(0);
  std::vector<std::int32_t> centres;
  for (std::int32_t first = 0; first < vertices; first += kBatch) {
    centres.resize(std::size_t(std::min(kBatch, vertices - first)));
    std::iota(centres.begin(), centres.end(), first);
    const SurfaceNeighborhoods batch = resampleNeighborhoods(mesh, topology, tangents, spacing, size, centres);
    for (std::size_t a = 0; a < centres.size(); ++a) {
      const std::span<const NeighborhoodMember> members = batch.membersOf(a);
      // The centre first (it is among its members at (0, 0)), then the others in vertex order.
      stencil.members.push_back({centres[a], 0.0f, 0.0f});
      for (const NeighborhoodMember& member : members)
        if (member.vertex != centres[a]) stencil.members.push_back(member);
      stencil.start.push_back(std::int64_t(stencil.members.size()));
    }
  }
  stencil.members.shrink_to_fit();
  return stencil;
}

}  // namespace texsynth
