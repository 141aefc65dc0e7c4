// The demo's lazy solid section: sketch, field, lazy solid on the mesh, and a cut.
#include "demo_lazy.h"

#include <chrono>
#include <sstream>

#include "demo_pixel.h"
#include "texsynth/core/error.h"
#include "texsynth/core/timing.h"
#include "texsynth/field/field_designer.h"
#include "texsynth/geometry/mesh_cut.h"
#include "texsynth/geometry/surface_projector.h"
#include "texsynth/io/image_io.h"
#include "texsynth/render/glyph_mesh.h"
#include "texsynth/render/view_up.h"
#include "texsynth/solid/solid_factory.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

constexpr int kCurvePoints = 9;
constexpr int kCutAxis = 0;  // x = half-way, the +x side removed
constexpr float kCutFraction = 0.5f;

json levelsJson(const LazySolid& solid, const std::vector<LazyLevelStats>& before) {
  json levels = json::array();
  for (int l = 0; l < solid.levels(); ++l) {
    const LazyLevelStats& now = solid.stats()[std::size_t(l)];
    const LazyLevelStats& was = before[std::size_t(l)];
    levels.push_back({{"level", l},
                      {"voxels", now.voxelsSynthesized - was.voxelsSynthesized},
                      {"seconds", now.seconds - was.seconds},
                      {"from_disk", now.fromDiskCache && !was.fromDiskCache}});
  }
  return levels;
}

}  // namespace

Sketch sketchOverTheTop(const Mesh& mesh) {
  const Box3f box = mesh.bounds();
  const Vec3f size = box.size(), centre = 0.5f * (box.min + box.max);
  const int along = size.x() >= size.z() ? 0 : 2;
  const SurfaceProjector projector(mesh);
  SketchCurve curve;
  curve.name = "over the top";
  curve.tangentAxis = 0;
  curve.normalAxis = 1;
  for (int i = 0; i < kCurvePoints; ++i) {
    Vec3f p = centre;
    p[along] += (float(i) / float(kCurvePoints - 1) - 0.5f) * 0.7f * size[along];
    p.y() = box.max.y();
    const Vec3f snapped = projector.closestPoint(p).position;
    if (curve.points.empty() || (snapped - curve.points.back()).norm() > 1e-4f * size.norm())
      curve.points.push_back(snapped);
  }
  Sketch sketch;
  if (curve.points.size() >= 2) sketch.curves.push_back(std::move(curve));
  return sketch;
}

json demoLazySolid(const Mesh& mesh, const Image& exemplar, const std::string& exemplarName, std::uint64_t seed,
                   const std::string& cacheDirectory, const RenderOptions& render,
                   const std::vector<std::pair<float, float>>& views,
                   const std::function<std::string(const std::string&)>& out) {
  json section = {{"exemplar", exemplarName}};
  auto start = std::chrono::steady_clock::now();
  const Box3f box = mesh.bounds();
  SolidRecipe recipe;
  recipe.method = SolidMethod::Lazy;
  recipe.exemplars = {exemplar};
  recipe.box = box;
  recipe.seed = seed;
  recipe.lazy.levels = 0;  // as many as the exemplar allows, as the command line
  recipe.lazy.cacheDirectory = cacheDirectory;
  const Sketch sketch = sketchOverTheTop(mesh);
  section["sketch_curves"] = sketch.curves.size();
  if (!sketch.curves.empty()) recipe.field = std::make_shared<const RotationField>(designField(mesh, sketch).rotations);
  section["field_seconds"] = secondsSince(start);

  start = std::chrono::steady_clock::now();
  SolidBuild build = buildSolid(recipe);
  SolidTexture& texture = *build.texture;
  const LazySolid& solid = *build.lazyParts.front().second;
  const SurfaceColorFunction colorAt = [&texture](const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals,
                                                  std::vector<Vec3f>& colors) {
    texture.prepare(points);
    colors = texture.evaluateColors(points, normals);
  };
  // The first picture's work from nothing: the coarsest level (built above) and what the views add.
  std::vector<LazyLevelStats> before(solid.stats().size());
  const Image picture = renderViews(mesh, &colorAt, views, render);
  section["first_picture_seconds"] = secondsSince(start);
  section["first_picture_levels"] = levelsJson(solid, before);

  start = std::chrono::steady_clock::now();
  before = solid.stats();
  const MeshCut opened = cutOpenMesh(coloredCopy(mesh, render.defaultColor), kCutAxis, kCutFraction,
                                     box.size().maxCoeff() / 512.0f, render.defaultColor);
  const Image cut = renderViews(opened.mesh, &colorAt, {anglesAboutUp(render.up, cutViewAngles(kCutAxis))}, render);
  section["cut_seconds"] = secondsSince(start);
  section["cut_levels"] = levelsJson(solid, before);
  writeImage(out("lazy_solid.png"), sideBySide({picture, cut}));
  return section;
}

std::string lazySolidMarkdown(const json& lazy) {
  std::ostringstream md;
  md << "## Lazy solid synthesis\n\n![the lazy solid following a sketched field, then cut open at x = 0.5]"
        "(lazy_solid.png)\n\n"
     << "`texsynth solid " << lazy["exemplar"].get<std::string>()
     << " --method lazy --mesh MESH --sketch S --render R --cut x=0.5`: a rotation field designed from "
     << lazy["sketch_curves"] << " sketch curve laid over the top of the mesh (" << fixed3(lazy["field_seconds"])
     << " s), then the solid texture synthesized on demand at exactly the voxels the views show (every level "
        "coarsest first; the coarsest once over the whole box, read from the disk cache on the next run), then "
        "the mesh cut open: the cut synthesizes only the voxels it exposes.\n\n";
  md << "| request | seconds | voxels per level, coarsest first |\n|---|---:|---|\n";
  for (const auto& [label, seconds, levels] :
       {std::tuple{"first picture (two views)", "first_picture_seconds", "first_picture_levels"},
        std::tuple{"cut x = 0.5", "cut_seconds", "cut_levels"}}) {
    md << "| " << label << " | " << fixed3(lazy[seconds]) << " | ";
    for (const json& level : lazy[levels]) {
      md << (level["level"].get<int>() > 0 ? " / " : "") << level["voxels"].get<std::int64_t>();
      if (level["from_disk"].get<bool>()) md << " (disk cache)";
    }
    md << " |\n";
  }
  md << "\n";
  return md.str();
}

}  // namespace texsynth::cli
