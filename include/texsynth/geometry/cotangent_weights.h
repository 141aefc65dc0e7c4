#pragma once
// Cotangent weights of a triangle mesh's edges: the discrete Laplace-Beltrami operator (Pinkall &
// Polthier 1993) that the tangent field's connection Laplacian (surface/tangent_field.h) and the
// relief smoothing (mesh_smoothing.h) are built on. Computed once per edge, in double precision,
// in an order that does not depend on the thread count.
#include <cstdint>
#include <vector>

#include "texsynth/core/mesh.h"

namespace texsynth {

// An undirected edge a < b and the sum over its triangles of half the cotangent of the angle
// opposite it (negative across an obtuse angle).
struct CotangentEdge {
  std::int32_t a = 0, b = 0;
  double weight = 0;
};

// Every edge of the mesh's triangles once, in ascending (a, b) order. Each cotangent is clamped
// to [-maxCotangent, maxCotangent], so that a near-degenerate triangle (a sine of 0) gives a
// finite weight of the cosine's sign. The triangles' indices must be valid; an edge from a
// vertex to itself (a degenerate triangle's) is left out.
std::vector<CotangentEdge> cotangentEdges(const Mesh& mesh, double maxCotangent);

}  // namespace texsynth
