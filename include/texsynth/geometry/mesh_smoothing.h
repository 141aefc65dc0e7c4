#pragma once
// Taubin's lambda|mu smoothing (Taubin 1995, "A signal processing approach to fair surface
// design"): a low-pass filter on vertex positions that removes relief a few edges wide without
// the shrinking of plain Laplacian smoothing. Surface synthesis lays its neighbourhoods out on a
// level's mesh smoothed so, because one vertex spacing is one exemplar pixel there and relief
// below that scale would otherwise stretch every neighbourhood (surface_synthesis.h).
#include "texsynth/core/mesh.h"
#include "texsynth/geometry/mesh_topology.h"

namespace texsynth {

// A copy of `mesh` whose interior vertices went through `iterations` pairs of a shrinking step
// (lambda = 0.5) and an inflating one (mu = -0.53) toward the cotangent-weighted mean of their
// edge neighbours, each vertex moving along its own normal only: a flat region stays exactly
// where it is and vertices keep their places on the surface, so only relief changes (a
// checkerboard of bumps is gone after 10 iterations; a sphere keeps its radius to 1%). Border
// vertices stay. Normals are recomputed (computed first where the mesh has none); colours and
// attributes are copied. Deterministic for any thread count. Throws ParameterError("iterations",
// ...) if negative.
Mesh taubinSmoothed(const Mesh& mesh, const MeshTopology& topology, int iterations);

}  // namespace texsynth
