#pragma once
// Local frames along a sketch curve (sketch-guided solid texturing §3): the curve is resampled
// densely, snapped to the surface (or projected onto its reference plane), and each sample gets
// a tangent and a normal; an axis assignment turns (tangent, normal, their cross product) into
// a right-handed frame.
#include <string>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/field/sketch.h"
#include "texsynth/geometry/surface_projector.h"

namespace texsynth {

struct CurveSample {
  Vec3f position = Vec3f::Zero();
  Vec3f tangent = Vec3f::UnitX();  // unit, along the drawing direction
  Vec3f normal = Vec3f::UnitZ();   // unit, orthogonal to the tangent
};

// Resamples `curve` every `spacing` (world units) along its length, snaps surface curves to the
// mesh and projects plane curves onto their plane. Throws InputError(source, ...) when a point
// lies farther than `tolerance` from the surface (or plane), or when the tangent becomes parallel
// to the normal. `projector` may be null only for plane curves.
std::vector<CurveSample> sampleCurve(const SketchCurve& curve, const SurfaceProjector* projector, float spacing,
                                     float tolerance, const std::string& source);

// Which local axis the tangent and the normal become, with their signs: 24 choices, all the
// right-handed frames made of +-tangent, +-normal and their cross product.
struct AxisAssignment {
  int tangentAxis = 0, normalAxis = 2;
  bool flipTangent = false, flipNormal = false;
};

// The assignments a curve's labels allow, the canonical one first: tangent -> x (or the
// label), normal -> the axis after the tangent's successor (x -> z, y -> x, z -> y; or the
// label), no flips.
std::vector<AxisAssignment> allowedAssignments(const SketchCurve& curve);

// The unit quaternion of the frame `assignment` makes from a sample.
Quatf frameRotation(const CurveSample& sample, const AxisAssignment& assignment);

}  // namespace texsynth
