#pragma once
// Every vertex's small flattened neighbourhood: the vertices within a size x size square of
// cells around it, at their unfolded offsets (surface_neighborhoods.h's members, for every
// vertex instead of a sparse set of centres). The comparison stencil of coordinate correction
// (surface_parallel.h): an output neighbourhood is read at the vertices themselves, where
// their colors are exact, instead of at resampled grid cells.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/geometry/mesh_topology.h"
#include "texsynth/surface/surface_neighborhoods.h"

namespace texsynth {

struct SurfaceStencil {
  int size = 0;  // odd; members lie within |dx|, |dy| <= size / 2 + 0.5 cells
  // CSR over vertices: vertex v's members (itself first, at (0, 0)), in increasing vertex
  // order after it.
  std::vector<std::int64_t> start;
  std::vector<NeighborhoodMember> members;

  std::size_t vertexCount() const { return start.empty() ? 0 : start.size() - 1; }
  std::span<const NeighborhoodMember> of(std::size_t v) const {
    return {members.data() + start[v], std::size_t(start[v + 1] - start[v])};
  }
};

// The stencil of every vertex of `mesh` (cells `spacing` apart along tangents[v] and
// -(normal x tangent), as resampleNeighborhoods unfolds them). Same result for any thread count.
// Throws as resampleNeighborhoods.
SurfaceStencil buildSurfaceStencil(const Mesh& mesh, const MeshTopology& topology, std::span<const Vec3f> tangents,
                                   float spacing, int size);

}  // namespace texsynth
