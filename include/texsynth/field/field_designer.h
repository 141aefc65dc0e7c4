#pragma once
// Designing a rotation field from sketch curves, one curve at a time (sketch-guided solid
// texturing §3). Each curve's frames become soft constraints on the grid nodes it passes
// through (a later curve replaces earlier targets on shared nodes); the field is the
// normalized harmonic interpolant of eq. 2. Signs follow the paper: the first point of the first
// curve gets w >= 0, the rest of that curve follows by continuity, and every later curve takes
// at each point the sign closest to the current field.
//
// Curves in Frame mode build frames from tangent, normal and cross product. The first curve
// uses its labels (default: tangent -> x, normal -> z); later curves use, of the assignments
// their labels allow, the one closest to the current field. Curves in Align mode (incremental
// refinement) rotate the current field's best-matching axis (+-x, +-y, +-z, or +-label) onto
// the tangent by the smallest rotation. Adding a curve keeps the solver's multigrid hierarchy
// and warm-starts from the current solution.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "texsynth/core/mesh.h"
#include "texsynth/core/progress.h"
#include "texsynth/field/curve_frames.h"
#include "texsynth/field/harmonic_solver.h"
#include "texsynth/field/rotation_field.h"
#include "texsynth/field/scale_field.h"
#include "texsynth/field/sketch.h"

namespace texsynth {

struct FieldDesignOptions {
  FieldGridOptions grid;
  HarmonicSolverOptions solver;  // weight w = 100 as in the paper
  // A sketch point farther than this from the surface (or its plane) is an error; as a
  // fraction of the mesh's bounding-box diagonal, in (0, 1].
  float snapTolerance = 0.03f;
  // Curve samples per grid spacing is 1 / sampleSpacing; in (0, 1] so no node is skipped.
  float sampleSpacing = 0.5f;
};

// Throws ParameterError naming the first invalid option.
void validateFieldDesignOptions(const FieldDesignOptions& options);

struct CurveUpdate {
  int samples = 0;            // curve samples placed
  int constrainedNodes = 0;   // grid nodes this curve constrains
  AxisAssignment assignment;  // Frame curves: the axes used
  int alignedAxis = -1;       // Align curves: the field axis rotated onto the tangent
  bool alignedAxisFlipped = false;
  HarmonicSolveStats solve;
  double seconds = 0;  // whole update: sampling, constraints and solve
};

class FieldDesigner {
 public:
  // The grid covers the mesh's bounding box plus the margin. Throws ParameterError for bad
  // options, InputError("mesh", ...) for a mesh without triangles.
  explicit FieldDesigner(const Mesh& mesh, const FieldDesignOptions& options = {});
  ~FieldDesigner();
  FieldDesigner(FieldDesigner&&) noexcept;
  FieldDesigner& operator=(FieldDesigner&&) noexcept;

  // Adds one curve and updates the field; `source` names the sketch in errors.
  CurveUpdate addCurve(const SketchCurve& curve, const std::string& source = "sketch");
  // Adds constraint frames directly (any quaternion signs; signs are chosen as for a curve:
  // continuity for the first batch, closest to the field afterwards). Positions must lie in
  // the grid (ParameterError("positions", ...) otherwise).
  CurveUpdate addFrames(const std::vector<Vec3f>& positions, const std::vector<Quatf>& rotations);

  // Replaces every constraint by these node targets, signs as given, and solves once: undoing a
  // curve keeps the targets the remaining curves set (in their order, later ones winning on shared
  // nodes) without re-deriving them curve by curve. No targets: the identity field again. Throws
  // ParameterError("targets", ...) for a node outside the grid or a non-unit rotation.
  HarmonicSolveStats setConstraints(const std::vector<std::pair<std::int64_t, Quatf>>& targets);

  const FieldGrid& grid() const;
  // The current field; identity everywhere before the first curve.
  const RotationField& field() const;
  bool hasField() const;
  // Every constrained node with its target rotation, by node index.
  std::vector<std::pair<std::int64_t, Quatf>> constraints() const;
  // The placed samples of every curve added, in order (for rendering).
  const std::vector<std::vector<CurveSample>>& curveSamples() const;
  // The same constraints solved again from scratch: a fresh solver and a zero start.
  RotationField solveFromScratch() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The whole sketch: every curve in order, then the scale field from the sketch's scale points.
struct FieldDesign {
  RotationField rotations;
  ScaleField scales;
  std::vector<std::vector<CurveSample>> curveSamples;
  std::vector<CurveUpdate> updates;
};
FieldDesign designField(const Mesh& mesh, const Sketch& sketch, const FieldDesignOptions& options = {},
                        Progress& progress = noProgress(), const std::string& source = "sketch");

}  // namespace texsynth
