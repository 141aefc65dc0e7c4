#pragma once
// Sketch curves: the user's guidance for a rotation field (sketch-guided solid texturing §3),
// and their JSON file format (docs/sketch-format.md).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/field/scale_field.h"

namespace texsynth {

enum class CurvePlacement {
  Surface,  // on the mesh surface: frame from tangent, outward normal and their cross product
  Plane,    // in the interior on a reference plane whose normal replaces the surface normal
};

enum class CurveMode {
  // Frames from the curve itself (tangent, normal, cross product): how the initial curves
  // establish the field.
  Frame,
  // Incremental refinement: the current field's axis (one of +-x, +-y, +-z) that best matches
  // the tangent is rotated onto it by the smallest rotation.
  Align,
};

struct SketchCurve {
  std::vector<Vec3f> points;  // world coordinates, at least 2, consecutive points distinct
  CurvePlacement placement = CurvePlacement::Surface;
  CurveMode mode = CurveMode::Frame;
  // Plane curves: the reference plane (normal need not be unit; point defaults to points[0]).
  Vec3f planeNormal = Vec3f::UnitZ();
  std::optional<Vec3f> planePoint;
  // Which local axis (0 = x, 1 = y, 2 = z) the tangent (and, for Frame curves, the normal)
  // becomes; unset lets the field choose (see FieldDesigner).
  std::optional<int> tangentAxis, normalAxis;
  std::string name;  // optional, for messages
};

struct Sketch {
  std::vector<SketchCurve> curves;
  std::vector<ScalePoint> scalePoints;
};

// Parses a sketch JSON document; `source` names it in errors. Throws InputError(source, ...)
// for malformed JSON, a wrong type, an unknown key or value, too few points, non-finite
// coordinates, repeated consecutive points or equal tangent and normal axes.
Sketch parseSketch(std::string_view json, const std::string& source);
// Reads and parses a sketch file.
Sketch readSketch(const std::string& path);
// The JSON text parseSketch reads back to an equal sketch.
std::string encodeSketch(const Sketch& sketch);

// "x", "y", "z" <-> 0, 1, 2.
const char* axisName(int axis);

}  // namespace texsynth
