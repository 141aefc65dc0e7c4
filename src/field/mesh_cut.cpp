#include "texsynth/field/mesh_cut.h"

#include <cmath>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/field/surface_projector.h"
#include "texsynth/render/glyph_mesh.h"

namespace texsynth {

MeshCut cutOpenMesh(const Mesh& mesh, int axis, float fraction, float capCell, const Vec3f& capColor, float capInset) {
  if (axis < 0 || axis > 2) throw ParameterError("cutAxis", "must be 0, 1 or 2, got " + std::to_string(axis));
  if (!(fraction > 0 && fraction < 1)) throw ParameterError("cutPosition", "must be in (0, 1)");
  if (!(capCell > 0) || !std::isfinite(capCell)) throw ParameterError("capCell", "must be finite and > 0");
  const Box3f box = mesh.bounds();
  MeshCut cut;
  cut.normal = Vec3f::Zero();
  cut.normal[axis] = 1;
  cut.offset = box.min[axis] + fraction * box.size()[axis];
  cut.mesh = clipMesh(mesh, cut.normal, cut.offset);
  const SurfaceProjector projector(mesh);
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  Vec3f du = Vec3f::Zero(), dw = Vec3f::Zero();
  du[u] = 0.5f * capCell;
  dw[w] = 0.5f * capCell;
  const int nu = int(std::ceil(box.size()[u] / capCell)), nw = int(std::ceil(box.size()[w] / capCell));
  for (int j = 0; j < nw; ++j)
    for (int i = 0; i < nu; ++i) {
      Vec3f p;
      p[axis] = cut.offset;
      p[u] = box.min[u] + (float(i) + 0.5f) * capCell;
      p[w] = box.min[w] + (float(j) + 0.5f) * capCell;
      if (!projector.inside(p)) continue;
      appendSquare(cut.mesh, p - capInset * cut.normal, du, dw, capColor);
      cut.cells.push_back({p, i, j});
    }
  return cut;
}

std::pair<float, float> cutViewAngles(int axis) {
  const float yaws[3] = {90 - 25, 25, 25}, pitches[3] = {20, 65, 20};
  return {yaws[axis], pitches[axis]};
}

}  // namespace texsynth
