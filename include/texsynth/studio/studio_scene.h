#pragma once
// The model the studio works on: the mesh (and a denser copy for per-vertex colours), the sketch
// curves the user drew on it, each with a server-made id, and the rotation field they design
// (sketch-guided solid texturing §3, through the same FieldDesigner as `texsynth field`).
// Not thread-safe: the server guards it with one lock.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "texsynth/core/mesh.h"
#include "texsynth/field/field_designer.h"
#include "texsynth/field/field_io.h"
#include "texsynth/field/sketch.h"

namespace texsynth::studio {

struct SceneCurve {
  std::string id;  // "curve-N", never reused within a scene
  SketchCurve curve;
  std::vector<Vec3f> samples;  // the placed (snapped) samples
  CurveUpdate update;          // when it was added: constrained nodes, the solve's iterations and time
  // The node targets it set (added or replaced), kept so that undoing another curve restores the
  // field from the remaining curves' targets in one solve.
  std::vector<std::pair<std::int64_t, Quatf>> targets;
};

// The command line's field design, solved to a looser tolerance so a curve answers at once (the
// field then differs from `texsynth field`'s by well under a tenth of a degree).
FieldDesignOptions interactiveFieldOptions();

class StudioScene {
 public:
  // `mesh` validated; normals are computed when missing. The display copy, coloured per vertex, has
  // `displayVertices` to 4x as many vertices where subdivision allows (midpoint subdivision keeps
  // the shape).
  StudioScene(std::string meshId, std::string meshName, Mesh mesh, std::size_t displayVertices = 100000,
              const FieldDesignOptions& fieldOptions = interactiveFieldOptions());

  const std::string& meshId() const { return meshId_; }
  const std::string& meshName() const { return meshName_; }
  const Mesh& mesh() const { return mesh_; }
  const Mesh& display() const { return display_; }
  const Box3f& bounds() const { return bounds_; }
  const FieldGrid& fieldGrid() const { return designer_->grid(); }

  // Adds a curve and re-solves the field. Throws ParameterError / InputError (a point off the
  // surface, an align curve first, ...) without changing anything.
  const SceneCurve& addCurve(const SketchCurve& curve);
  // HttpError 404 for an unknown id. The field is solved again from the targets the remaining
  // curves set (in drawing order), so later curves keep the frames they were drawn with.
  void removeCurve(const std::string& id);
  // Replaces every curve (a loaded sketch); all or nothing.
  void replaceSketch(const Sketch& sketch);
  const std::vector<SceneCurve>& curves() const { return curves_; }
  Sketch sketch() const;

  // Counts field changes (0: no curve yet).
  int revision() const { return revision_; }
  // The current field; null while no curve is drawn (the identity).
  std::shared_ptr<const RotationField> field() const { return field_; }
  FieldFile fieldFile() const;

  // Axis glyphs on the surface, about `across` along the longest side: per glyph its position and
  // the field's local x, y and z axes; and every curve's samples.
  nlohmann::json glyphs(int across) const;

 private:
  // Every remaining curve's targets, in drawing order (a later curve wins on a shared node).
  std::vector<std::pair<std::int64_t, Quatf>> combinedTargets(const std::vector<SceneCurve>& curves) const;
  // Adds a curve to `designer` and records the node targets it changed; `source` names it in errors.
  static SceneCurve added(FieldDesigner& designer, const SketchCurve& curve, std::string id, const std::string& source);

  std::string meshId_, meshName_;
  Mesh mesh_, display_;
  Box3f bounds_;
  FieldDesignOptions fieldOptions_;
  std::unique_ptr<FieldDesigner> designer_;
  std::vector<SceneCurve> curves_;
  std::shared_ptr<const RotationField> field_;
  int revision_ = 0, nextCurve_ = 0;
};

}  // namespace texsynth::studio
