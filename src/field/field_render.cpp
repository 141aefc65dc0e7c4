#include "texsynth/field/field_render.h"

#include <cmath>
#include <map>
#include <tuple>

#include "texsynth/core/error.h"
#include "texsynth/field/surface_projector.h"
#include "texsynth/render/glyph_mesh.h"

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
    const float offset = box.min[axis] + options.cutPosition * box.size()[axis];
    Vec3f normal = Vec3f::Zero();
    normal[axis] = 1;
    Mesh cut = clipMesh(base, normal, offset);
    // A cap of small squares where the plane is inside the mesh, glyphs on a coarser lattice.
    SurfaceProjector projector(mesh);
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    const int capPerGlyph = 6;
    const float capCell = cell / float(capPerGlyph);
    Vec3f du = Vec3f::Zero(), dw = Vec3f::Zero();
    du[u] = 0.5f * capCell;
    dw[w] = 0.5f * capCell;
    const int nu = int(std::ceil(box.size()[u] / capCell)), nw = int(std::ceil(box.size()[w] / capCell));
    for (int j = 0; j < nw; ++j)
      for (int i = 0; i < nu; ++i) {
        Vec3f p;
        p[axis] = offset;
        p[u] = box.min[u] + (float(i) + 0.5f) * capCell;
        p[w] = box.min[w] + (float(j) + 0.5f) * capCell;
        if (!projector.inside(p)) continue;
        appendSquare(cut, p - 0.2f * radius * normal, du, dw, kCapColor);
        if (i % capPerGlyph == capPerGlyph / 2 && j % capPerGlyph == capPerGlyph / 2)
          appendAxisGlyph(cut, p, field.frame(p), 1.6f * length, 1.3f * radius, true);
      }
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
    // Look at the cut face from the removed side, a little from above and aside.
    const float yaws[3] = {90 - 25, 25, 25}, pitches[3] = {20, 65, 20};
    view.yawDegrees = yaws[axis];
    view.pitchDegrees = pitches[axis];
    if (!cut.triangles.empty()) views.push_back(renderMesh(cut, view));
  }
  Image montage(options.render.width * int(views.size()), options.render.height, 3);
  for (std::size_t v = 0; v < views.size(); ++v)
    for (int y = 0; y < views[v].height; ++y)
      std::copy_n(views[v].pixel(0, y), std::size_t(views[v].width) * 3,
                  montage.pixel(int(v) * options.render.width, y));
  return montage;
}

}  // namespace texsynth
