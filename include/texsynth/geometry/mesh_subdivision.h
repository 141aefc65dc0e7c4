#pragma once
// Denser copies of a mesh for per-vertex colouring (the studio's preview): midpoint subdivision
// splits every triangle into four through its edge midpoints, so the shape stays exactly the same
// and colours evaluated at the vertices show finer detail.
#include <cstddef>

#include "texsynth/core/mesh.h"

namespace texsynth {

// One level: one new vertex per edge (shared by its triangles). Normals (when present) and
// colours (when present) are averaged and normals renormalized, so the shading stays smooth;
// other attributes are dropped. Throws InputError("mesh", ...) for an invalid mesh.
Mesh subdivideMidpoint(const Mesh& mesh);

// Subdivides until the mesh has at least `minVertices` vertices or one more level would exceed
// `maxVertices`; returns a copy when neither applies.
Mesh subdivideToVertices(const Mesh& mesh, std::size_t minVertices, std::size_t maxVertices);

}  // namespace texsynth
