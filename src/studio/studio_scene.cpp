// The studio's model, sketch and field.
#include "texsynth/studio/studio_scene.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "texsynth/core/error.h"
#include "texsynth/geometry/mesh_subdivision.h"
#include "texsynth/studio/http_error.h"
#include "texsynth/studio/texturable_mesh.h"

namespace texsynth::studio {

namespace {

nlohmann::json vec(const Vec3f& v) {
  return {v.x(), v.y(), v.z()};
}

}  // namespace

FieldDesignOptions interactiveFieldOptions() {
  FieldDesignOptions options;
  options.solver.tolerance = 1e-3;
  return options;
}

StudioScene::StudioScene(std::string meshId, std::string meshName, Mesh mesh, std::size_t displayVertices,
                         const FieldDesignOptions& fieldOptions)
    : meshId_(std::move(meshId)), meshName_(std::move(meshName)), mesh_(std::move(mesh)), fieldOptions_(fieldOptions) {
  mesh_.validate(meshName_);
  requireTexturableMesh(mesh_, meshName_);
  if (mesh_.normals.empty()) mesh_.computeNormals();
  mesh_.colors.clear();
  mesh_.attributes.clear();
  display_ = subdivideToVertices(mesh_, displayVertices, 4 * displayVertices);
  bounds_ = mesh_.bounds();
  designer_ = std::make_unique<FieldDesigner>(mesh_, fieldOptions_);
}

SceneCurve StudioScene::added(FieldDesigner& designer, const SketchCurve& curve, std::string id,
                              const std::string& source) {
  const auto before = designer.constraints();
  SceneCurve entry{std::move(id), curve, {}, designer.addCurve(curve, source), {}};
  for (const CurveSample& s : designer.curveSamples().back()) entry.samples.push_back(s.position);
  // What this curve changed: new nodes and replaced targets (both lists are in node order).
  auto old = before.begin();
  for (const auto& [node, target] : designer.constraints()) {
    while (old != before.end() && old->first < node) ++old;
    const bool same = old != before.end() && old->first == node && old->second.coeffs() == target.coeffs();
    if (!same) entry.targets.push_back({node, target});
  }
  return entry;
}

std::vector<std::pair<std::int64_t, Quatf>> StudioScene::combinedTargets(const std::vector<SceneCurve>& curves) const {
  std::map<std::int64_t, Quatf> targets;
  for (const SceneCurve& c : curves)
    for (const auto& [node, q] : c.targets) targets.insert_or_assign(node, q);
  return {targets.begin(), targets.end()};
}

const SceneCurve& StudioScene::addCurve(const SketchCurve& curve) {
  try {
    curves_.push_back(added(*designer_, curve, "curve-" + std::to_string(nextCurve_ + 1), "curve"));
  } catch (...) {
    // A rejected curve may leave the designer half-changed: back to the accepted curves' targets.
    designer_->setConstraints(combinedTargets(curves_));
    throw;
  }
  ++nextCurve_;
  field_ = std::make_shared<const RotationField>(designer_->field());
  ++revision_;
  return curves_.back();
}

void StudioScene::removeCurve(const std::string& id) {
  const auto it = std::find_if(curves_.begin(), curves_.end(), [&](const SceneCurve& c) { return c.id == id; });
  if (it == curves_.end()) throw notFound("curve '" + id + "'");
  std::vector<SceneCurve> kept = curves_;
  kept.erase(kept.begin() + (it - curves_.begin()));
  designer_->setConstraints(combinedTargets(kept));
  curves_ = std::move(kept);
  field_ = curves_.empty() ? nullptr : std::make_shared<const RotationField>(designer_->field());
  ++revision_;
}

void StudioScene::replaceSketch(const Sketch& sketch) {
  // The same sequence as `texsynth field --sketch`: one curve after the other on a fresh designer.
  auto designer = std::make_unique<FieldDesigner>(mesh_, fieldOptions_);
  std::vector<SceneCurve> curves;
  int next = nextCurve_;
  for (const SketchCurve& curve : sketch.curves)
    curves.push_back(added(*designer, curve, "curve-" + std::to_string(++next), "sketch"));
  designer_ = std::move(designer);
  curves_ = std::move(curves);
  nextCurve_ = next;
  field_ = curves_.empty() ? nullptr : std::make_shared<const RotationField>(designer_->field());
  ++revision_;
}

Sketch StudioScene::sketch() const {
  Sketch sketch;
  for (const SceneCurve& c : curves_) sketch.curves.push_back(c.curve);
  return sketch;
}

FieldFile StudioScene::fieldFile() const {
  FieldFile file;
  file.rotations = field_ ? *field_ : RotationField(designer_->grid());
  return file;
}

nlohmann::json StudioScene::glyphs(int across) const {
  across = std::clamp(across, 2, 100);
  const float spacing = bounds_.size().maxCoeff() / float(across);
  // Per cell of a grid `spacing` apart, the (display) mesh vertex closest to the cell's centre.
  std::unordered_map<std::int64_t, std::pair<float, int>> best;
  const Vec3i cells = ((bounds_.size() / spacing).array().floor().cast<int>() + 1).matrix();
  for (std::size_t v = 0; v < display_.positions.size(); ++v) {
    const Vec3f local = (display_.positions[v] - bounds_.min) / spacing;
    const Vec3i cell = local.array().floor().cast<int>().min(cells.array() - 1).max(0).matrix();
    const std::int64_t key = (std::int64_t(cell.z()) * cells.y() + cell.y()) * cells.x() + cell.x();
    const float distance = (local - cell.cast<float>() - Vec3f::Constant(0.5f)).squaredNorm();
    const auto [it, added] = best.try_emplace(key, distance, int(v));
    if (!added && distance < it->second.first) it->second = {distance, int(v)};
  }
  std::vector<std::pair<std::int64_t, int>> chosen;
  for (const auto& [key, entry] : best) chosen.push_back({key, entry.second});
  std::sort(chosen.begin(), chosen.end());
  nlohmann::json glyphs = nlohmann::json::array();
  for (const auto& [key, v] : chosen) {
    const Vec3f& p = display_.positions[std::size_t(v)];
    const Frame frame = field_ ? field_->frame(p) : Frame{};
    glyphs.push_back({{"position", vec(p)}, {"x", vec(frame.x)}, {"y", vec(frame.y)}, {"z", vec(frame.z)}});
  }
  nlohmann::json curves = nlohmann::json::array();
  for (const SceneCurve& c : curves_) {
    nlohmann::json points = nlohmann::json::array();
    for (const Vec3f& p : c.samples) points.push_back(vec(p));
    curves.push_back({{"id", c.id}, {"samples", points}});
  }
  return {{"revision", revision_}, {"spacing", spacing}, {"glyphs", glyphs}, {"curves", curves}};
}

}  // namespace texsynth::studio
