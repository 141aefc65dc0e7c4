#pragma once
// Resampled output neighbourhoods on a mesh (surface synthesis by discrete optimization, §2.2.1:
// x_p = W_p x). Each active vertex's neighbourhood is a regular size x size grid in its tangent
// frame; every grid cell is a precomputed convex combination of at most three vertices, found by
// unfolding the triangles around the vertex into the plane (Turk 2001, Wei & Levoy 2001). Also
// the sparse set of active vertices (Kwatra et al. 2005's neighbourhood centres, on a mesh) and,
// both ways round, which vertices lie in which neighbourhood.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/geometry/mesh_topology.h"

namespace texsynth {

// One grid cell of a neighbourhood: sum_i weight[i] * x[vertex[i]]. Weights are >= 0 and sum to
// 1; an unused corner has weight 0 and repeats a used vertex, so every index is valid.
struct NeighborhoodCell {
  std::array<std::int32_t, 3> vertex{};
  std::array<float, 3> weight{};
  // False where no unfolded triangle covers the cell (past a border, around a part thinner than
  // the neighbourhood, in a gap curvature opens): its weights then only continue the nearest
  // covered point, and synthesis leaves the cell out of its comparisons.
  bool covered = true;
};

// A vertex inside a neighbourhood, at this unfolded offset from the centre, in cells (the same
// axes as the cells: +dx along the tangent, +dy along -(normal x tangent)).
struct NeighborhoodMember {
  std::int32_t vertex = 0;
  float dx = 0, dy = 0;
};

// The transpose: vertex v lies in active neighbourhood `neighborhood` at offset (dx, dy).
struct CoveringEntry {
  std::int32_t neighborhood = 0;
  float dx = 0, dy = 0;
};

// W_p for a set of active vertices. One output "pixel" is `spacing` world units. Cell (dx, dy),
// dx, dy in [-radius, radius], of the neighbourhood of vertex p lies at the tangent-plane offset
// spacing * (dx * t - dy * b) from p, with t = tangents[p] and b = n x t (n the vertex normal):
// exemplar x follows t and exemplar y (down the image) follows -b, so the texture is not mirrored
// when the surface is seen from outside (from where n points).
struct SurfaceNeighborhoods {
  int size = 0;    // odd; cells per side
  int radius = 0;  // size / 2
  float spacing = 0;
  // The active vertices (the sparse set X of texture optimization); neighbourhood a is centred
  // on vertex centres[a].
  std::vector<std::int32_t> centres;
  // centres.size() * size * size; neighbourhood a's cell (dx, dy) at
  // a * size * size + (dy + radius) * size + (dx + radius).
  std::vector<NeighborhoodCell> cells;
  // CSR over neighbourhoods (centres.size() + 1 offsets): the vertices whose unfolded position
  // lies in the size x size square (|dx|, |dy| <= radius + 0.5), each once (at the position where
  // the unfolding first reached it), in increasing vertex order; the centre itself is at (0, 0).
  std::vector<std::int64_t> memberStart;
  std::vector<NeighborhoodMember> members;
  // CSR over vertices (vertexCount + 1 offsets): the transpose of members, each vertex's entries
  // in increasing neighbourhood order. A vertex in no square has none.
  std::vector<std::int64_t> coveringStart;
  std::vector<CoveringEntry> covering;

  std::size_t activeCount() const { return centres.size(); }
  std::size_t vertexCount() const { return coveringStart.empty() ? 0 : coveringStart.size() - 1; }
  int cellCount() const { return size * size; }
  // Neighbourhood a's cells, row by row (dy = -radius first), each row dx = -radius first.
  std::span<const NeighborhoodCell> cellsOf(std::size_t a) const {
    return {cells.data() + a * std::size_t(cellCount()), std::size_t(cellCount())};
  }
  const NeighborhoodCell& cell(std::size_t a, int dx, int dy) const {
    return cells[a * std::size_t(cellCount()) + std::size_t((dy + radius) * size + dx + radius)];
  }
  std::span<const NeighborhoodMember> membersOf(std::size_t a) const {
    return {members.data() + memberStart[a], std::size_t(memberStart[a + 1] - memberStart[a])};
  }
  std::span<const CoveringEntry> coveringOf(std::size_t vertex) const {
    return {covering.data() + coveringStart[vertex], std::size_t(coveringStart[vertex + 1] - coveringStart[vertex])};
  }
  // x_p = W_p x for neighbourhood a: `values` holds `channels` floats per vertex; `out` receives
  // cellCount() * channels floats in cell order.
  void resample(std::size_t a, std::span<const float> values, int channels, std::span<float> out) const;
};

// The active centres, in increasing vertex order: a deterministic maximal Poisson-disk subset of
// the vertices with radius R = stride * spacing, taken greedily in an order hashed from `seed`.
// Every vertex lies within R (Euclidean) of a centre and centres are more than R apart, so they
// are about `stride` cells apart (Kwatra et al.'s centres N/4 apart, on a mesh). Such a set is
// sparser than a grid of that pitch: about 0.6 / stride^2 centres per vertex when there is one
// vertex per cell (a grid has 1 / stride^2); pass a smaller spacing for more. Vertices whose
// normals are more than 90 degrees apart never exclude each other (the two sides of a thin sheet
// each get their own centres); without normals all distances count. stride 1 returns every
// vertex. Same result for any thread count. Throws ParameterError("spacing" / "stride", ...).
std::vector<std::int32_t> selectActiveCentres(const Mesh& mesh, float spacing, int stride, std::uint64_t seed = 0);

// W_p (cells), members and covering for the given centres. The neighbourhood is flattened by
// walking across triangles from the centre vertex, not by projection onto the tangent plane:
// - the centre's one-ring is laid out as a geodesic polar map (true edge lengths, corner angles
//   scaled to sum to 2 pi around an interior vertex; left as they are at a border vertex unless
//   they exceed 2 pi), turned so that the tangent points along +dx: the tangent is located in the
//   one-ring triangle whose wedge holds its projection (else the ring is turned to agree best with
//   the projections of its edges);
// - every further triangle is unfolded rigidly into the plane across the edge it shares with an
//   already unfolded one, nearest first (by unfolded centroid, to 1/16 cell), each triangle
//   once. The walk stops at triangles whose bounding box misses the square |dx|, |dy| <= radius + 0.5.
// Each cell centre takes the barycentric weights of the first unfolded triangle containing it (so
// cell (0, 0) is exactly the centre vertex, and a linear function on a flat or developable region
// is reproduced exactly).
// A cell no triangle covers (past a mesh border, or in a gap the angle deficit of a curved region
// opens between unfolded triangles) takes the combination of the nearest point of the unfolded
// triangles (on the border of the nearest one, first in unfolding order among equals), so the
// texture is continued as clamp-to-edge. A centre in no triangle gets weight 1 on itself
// everywhere. Cell weights may reference vertices outside the member square.
// Normals are mesh.normals; a tangent not perpendicular to its normal is projected (and any
// perpendicular direction used if it is parallel). Parallel over centres; the result is the same
// for any thread count. Throws ParameterError("spacing" / "size" / "tangents" / "centres" /
// "mesh" / "topology", ...) for a non-positive spacing, an even or non-positive size, tangents or
// normals not one per vertex, a centre out of range, or a topology of another mesh.
SurfaceNeighborhoods resampleNeighborhoods(const Mesh& mesh, const MeshTopology& topology,
                                           std::span<const Vec3f> tangents, float spacing, int size,
                                           std::span<const std::int32_t> centres);

}  // namespace texsynth
