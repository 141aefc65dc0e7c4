#pragma once
// Near-uniform retiling of a triangle mesh at a requested vertex count: CGAL's isotropic
// remeshing (split long edges, collapse short ones, flip towards valence 6, tangential
// relaxation, projection back onto the input) with the edge length a regular triangulation of
// the surface area would have. The levels of the surface synthesizer's mesh hierarchy.
#include <string>

#include "texsynth/core/mesh.h"

namespace texsynth {

struct RetileOptions {
  // Vertices wanted (> 0). The edge length asked of CGAL is that of a regular triangulation of
  // the surface area A with N vertices, e = sqrt(2 A / (sqrt(3) N)), 8% longer (remeshing leaves
  // edges that much shorter than asked); that lands within a few percent on scanned and modelled
  // meshes. A result off by more than `tolerance` is retiled again (see retileMesh).
  int targetVertices = 0;
  // Rounds of split / collapse / flip / relax (CGAL's number_of_iterations), in [1, 100]. 3 gives
  // near-uniform edges (edge length spread 13%, 1st..99th percentile 0.72..1.33 of the mean on
  // the CGAL demo meshes); 2 gives 15%, 5 gives 12.5%; the time grows about linearly.
  int iterations = 3;
  // Relative vertex-count error that triggers another pass, in (0, 1).
  float tolerance = 0.1f;
};

// Retiles `input` (validated by MeshTopology first, so a bad mesh gives one InputError(source,
// ...)). Borders stay on the input's border polylines: their edges are split and collapsed to the
// same length as the rest and their vertices slide along them. Vertices where separate fans meet
// are split first; vertices no face uses are dropped. When the count misses by more than the
// tolerance (a very regular input coarser than the target, such as a subdivided icosahedron,
// whose edges all split at once), the input is retiled again with its edges first split to half
// the length, then once more with the length corrected by V ~ 1 / e^2; the closest pass wins.
// The result has normals, no colours or attributes. Throws ParameterError("targetVertices" |
// "iterations" | "tolerance", ...). Deterministic and independent of the thread count (CGAL
// runs on the calling thread).
Mesh retileMesh(const Mesh& input, const RetileOptions& options, const std::string& source);

}  // namespace texsynth
