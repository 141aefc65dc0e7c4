#include "texsynth/geometry/mesh_cut.h"

#include <cmath>
#include <string>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/geometry/surface_projector.h"

namespace texsynth {
namespace {

// A flat square centred at `centre`, spanned by half-edge vectors u and v, facing `normal`.
void appendCapSquare(Mesh& mesh, const Vec3f& centre, const Vec3f& u, const Vec3f& v, const Vec3f& normal,
                     const Vec3f& color) {
  const int base = int(mesh.positions.size());
  const Vec3f corners[4] = {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
  for (const Vec3f& p : corners) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(normal);
    mesh.colors.push_back(color);
  }
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}

}  // namespace

Mesh clipMesh(const Mesh& mesh, const Vec3f& normal, float offset) {
  Mesh out;
  std::vector<int> remap(mesh.positions.size(), -1);
  const bool colors = mesh.colors.size() == mesh.positions.size();
  const bool normals = mesh.normals.size() == mesh.positions.size();
  for (const Vec3i& t : mesh.triangles) {
    Vec3f centroid = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0f;
    if (normal.dot(centroid) > offset) continue;
    Vec3i kept;
    for (int k = 0; k < 3; ++k) {
      int& r = remap[std::size_t(t[k])];
      if (r < 0) {
        r = int(out.positions.size());
        out.positions.push_back(mesh.positions[t[k]]);
        if (colors) out.colors.push_back(mesh.colors[t[k]]);
        if (normals) out.normals.push_back(mesh.normals[t[k]]);
      }
      kept[k] = r;
    }
    out.triangles.push_back(kept);
  }
  return out;
}

MeshCut cutOpenMesh(const Mesh& mesh, int axis, float fraction, float capCell, const Vec3f& capColor, float capInset) {
  if (axis < 0 || axis > 2) throw ParameterError("cutAxis", "must be 0, 1 or 2, got " + std::to_string(axis));
  if (!(fraction > 0 && fraction < 1)) throw ParameterError("cutPosition", "must be in (0, 1)");
  if (!(capCell > 0) || !std::isfinite(capCell)) throw ParameterError("capCell", "must be finite and > 0");
  if (mesh.colors.size() != mesh.positions.size() || mesh.normals.size() != mesh.positions.size())
    throw ParameterError("mesh", "needs a colour and a normal per vertex before it is cut open (coloredCopy)");
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
      appendCapSquare(cut.mesh, p - capInset * cut.normal, du, dw, cut.normal, capColor);
      cut.cells.push_back({p, i, j});
    }
  return cut;
}

std::pair<float, float> cutViewAngles(int axis) {
  const float yaws[3] = {90 - 25, 25, 25}, pitches[3] = {20, 65, 20};
  return {yaws[axis], pitches[axis]};
}

}  // namespace texsynth
