#pragma once
// A mesh cut open by an axis-aligned plane, to look inside a volume: the triangles on the
// plane's low side and a cap of small squares wherever the plane lies inside the mesh. Field
// glyph renders put glyphs on the cap; solid textures colour it with their interior.
#include <utility>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

struct MeshCut {
  struct CapCell {
    Vec3f centre;
    int i = 0, j = 0;  // lattice index along the plane's two axes ((axis + 1) % 3, (axis + 2) % 3)
  };
  Mesh mesh;                   // kept triangles (as clipMesh) plus the cap squares
  std::vector<CapCell> cells;  // the cap's squares, in lattice order
  Vec3f normal = Vec3f::UnitZ();
  float offset = 0;  // the plane: normal . p = offset
};

// The triangles whose centroid satisfies normal . p <= offset (a half-space cut), with their
// vertices, colours and normals.
Mesh clipMesh(const Mesh& mesh, const Vec3f& normal, float offset);

// Cuts `mesh` (which should be closed: the cap uses SurfaceProjector::inside) at `fraction` in
// (0, 1) of its bounding box along `axis` (0, 1, 2), removing the +axis side. The cap squares
// have side `capCell` (> 0), colour `capColor`, normal +axis, and sit `capInset` below the plane
// (so that glyphs drawn on the plane stay in front). `mesh` needs a colour and a normal per
// vertex (render's coloredCopy). Throws ParameterError for a bad axis, fraction or cell, and
// ParameterError("mesh", ...) for a mesh without colours or normals.
MeshCut cutOpenMesh(const Mesh& mesh, int axis, float fraction, float capCell, const Vec3f& capColor,
                    float capInset = 0.0f);

// (yaw, pitch) in degrees of a camera that looks at the cut face from the removed side, a
// little from above and aside (RenderOptions' orbit convention).
std::pair<float, float> cutViewAngles(int axis);

}  // namespace texsynth
