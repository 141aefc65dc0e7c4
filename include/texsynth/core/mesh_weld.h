#pragma once
// Welding: one vertex per position. Files with texture coordinates or hard normals store a vertex
// once per side of every seam (OBJ corners split by texsynth's reader, PLY and glTF as written);
// algorithms that walk the surface (retiling, surface synthesis) would see the seams as borders.
#include <vector>

#include "texsynth/core/mesh.h"

namespace texsynth {

struct WeldedMesh {
  // Positions and colors of each position's first vertex, normals recomputed where vertices merged,
  // no attributes (they differ across the seams), the triangles that are not degenerate after it.
  Mesh mesh;
  std::vector<int> vertexOf;  // per input vertex: its vertex in `mesh`
};

// Merges vertices with exactly equal positions; vertices keep their order (the first of each
// position). A mesh without such copies comes back unchanged, attributes included.
WeldedMesh weldCoincidentVertices(const Mesh& mesh);

}  // namespace texsynth
