#pragma once
// Shared fixtures of the field tests: a unit cube and small grids, so every test runs fast.
#include <algorithm>

#include "test_support.h"
#include "texsynth/field/field_designer.h"
#include "texsynth/render/primitives.h"

namespace texsynth::test {

inline Mesh unitCube() {
  return makeBoxMesh(Vec3f::Zero(), Vec3f::Ones());
}

inline FieldDesignOptions smallGrid(int cells = 12) {
  FieldDesignOptions options;
  options.grid.shortestCells = cells;
  options.grid.margin = 0;
  return options;
}

inline SketchCurve surfaceCurve(std::vector<Vec3f> points, CurveMode mode = CurveMode::Frame) {
  SketchCurve c;
  c.points = std::move(points);
  c.mode = mode;
  return c;
}

// Largest rotation angle between two fields on the same grid, in degrees.
inline float maxAngleDifference(const RotationField& a, const RotationField& b) {
  float worst = 0;
  for (std::int64_t i = 0; i < a.grid().nodeCount(); ++i)
    worst = std::max(worst, rotationAngleDegrees(a.at(i), b.at(i)));
  return worst;
}

}  // namespace texsynth::test
