// The studio's checks of a mesh beyond what its file format demands.
#include "texsynth/studio/texturable_mesh.h"

#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth::studio {

void requireTexturableMesh(const Mesh& mesh, const std::string& name) {
  if (mesh.triangles.empty()) throw InputError(name, "the mesh has no triangles");
  const Box3f box = mesh.bounds();
  // An extent below float resolution at the mesh's coordinates is no extent: one point, shifted.
  const float extent = box.size().maxCoeff();
  const float magnitude = std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
  if (!(extent > 1e-6f * magnitude) || !(extent > 0))
    throw InputError(name, "every vertex is at one point: the mesh has no extent to texture");
  if (!(mesh.surfaceArea() > 1e-12 * double(extent) * double(extent)))
    throw InputError(name, "every triangle has zero area (the vertices lie on a line): nothing to texture");
}

}  // namespace texsynth::studio
