#include "texsynth/field/field_render.h"

#include <cmath>
#include <map>
#include <tuple>

#include "texsynth/core/error.h"
#include "texsynth/geometry/mesh_cut.h"
#include "texsynth/render/glyph_mesh.h"
#include "texsynth/render/view_up.h"

namespace texsynth {

namespace {

const Vec3f kSurfaceColor{0.82f, 0.82f, 0.80f};
const Vec3f kCapColor{0.95f, 0.90f, 0.78f};
const Vec3f kCurveColor{1.0f, 0.80f, 0.05f};

// One vertex per occupied cell of a `cell`-sized grid: the one nearest the cell's centre
// (ties to the smaller index), so glyphs spread evenly whatever the tessellation.
std::vector<int> spreadVertices(const Mesh& mesh, float cell) {
  const Box3f box = mesh.bounds();
  std::map<std::tuple<int, int, int>, std::pair<float, int>> best;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    Vec3f g = (mesh.positions[i] - box.min) / cell;
    auto key = std::make_tuple(int(g.x()), int(g.y()), int(g.z()));
    Vec3f centre(std::floor(g.x()) + 0.5f, std::floor(g.y()) + 0.5f, std::floor(g.z()) + 0.5f);
    float d = (g - centre).squaredNorm();
    auto [it, inserted] = best.try_emplace(key, d, int(i));
    if (!inserted && d < it->second.first) it->second = {d, int(i)};
  }
  std::vector<int> out;
  for (const auto& [key, entry] : best) out.push_back(entry.second);
  return out;
}

}  // namespace

void validateFieldRenderOptions(const FieldRenderOptions& options) {
  validateRenderOptions(options.render);
  if (options.glyphsAcross < 2 || options.glyphsAcross > 200)
    throw ParameterError("glyphsAcross", "must be in [2, 200]");
  if (options.views.empty() && !options.showCut) throw ParameterError("views", "need at least one view or the cut");
  if (options.cutAxis < 0 || options.cutAxis > 2) throw ParameterError("cutAxis", "must be 0, 1 or 2");
  if (!(options.cutPosition > 0 && options.cutPosition < 1)) throw ParameterError("cutPosition", "must be in (0, 1)");
}

Image renderFieldGlyphs(const Mesh& mesh, const RotationField& field, const std::vector<std::vector<Vec3f>>& curves,
                        const FieldRenderOptions& options) {
  validateFieldRenderOptions(options);
  mesh.validate("mesh");
  if (mesh.triangles.empty()) throw InputError("mesh", "has no triangles to render");
  const Box3f box = mesh.bounds();
  const float cell = box.size().maxCoeff() / float(options.glyphsAcross);
  const float length = 0.42f * cell, radius = 0.055f * cell;

  Mesh base = coloredCopy(mesh, kSurfaceColor);
  Mesh surface = base;
  for (int v : spreadVertices(base, cell)) {
    Vec3f p = base.positions[std::size_t(v)] + 0.5f * radius * base.normals[std::size_t(v)];
    appendAxisGlyph(surface, p, field.frame(p), length, radius);
  }
  for (const auto& curve : curves) appendPolyline(surface, curve, 1.6f * radius, kCurveColor);

  std::vector<Image> views;
  for (auto [yaw, pitch] : options.views) {
    RenderOptions view = options.render;
    view.yawDegrees = yaw;
    view.pitchDegrees = pitch;
    views.push_back(renderMesh(surface, view));
  }
  if (options.showCut) {
    const int axis = options.cutAxis;
    // A cap of small squares where the plane is inside the mesh, glyphs on a coarser lattice.
    const int capPerGlyph = 6;
    MeshCut opened = cutOpenMesh(base, axis, options.cutPosition, cell / float(capPerGlyph), kCapColor, 0.2f * radius);
    Mesh& cut = opened.mesh;
    const float offset = opened.offset;
    for (const MeshCut::CapCell& c : opened.cells)
      if (c.i % capPerGlyph == capPerGlyph / 2 && c.j % capPerGlyph == capPerGlyph / 2)
        appendAxisGlyph(cut, c.centre, field.frame(c.centre), 1.6f * length, 1.3f * radius, true);
    for (const auto& curve : curves) {
      // Only the parts of curves that survive the cut.
      std::vector<Vec3f> piece;
      for (const Vec3f& p : curve) {
        // Curves drawn on the cut plane itself stay visible.
        if (p[axis] <= offset + 0.25f * cell) {
          piece.push_back(p);
        } else {
          appendPolyline(cut, piece, 1.6f * radius, kCurveColor);
          piece.clear();
        }
      }
      appendPolyline(cut, piece, 1.6f * radius, kCurveColor);
    }
    RenderOptions view = options.render;
    std::tie(view.yawDegrees, view.pitchDegrees) = anglesAboutUp(view.up, cutViewAngles(axis));
    if (!cut.triangles.empty()) views.push_back(renderMesh(cut, view));
  }
  return sideBySide(views);
}

}  // namespace texsynth
