// The properties sketch-guided solid texturing §3 promises of a designed rotation field.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "field_test_support.h"
#include "texsynth/core/parallel.h"

using namespace texsynth;
using test::maxAngleDifference;
using test::smallGrid;
using test::surfaceCurve;
using test::unitCube;

namespace {

// Two curves on different faces: a field with real variation.
FieldDesigner twoCurveDesigner(int cells = 12) {
  FieldDesigner d(unitCube(), smallGrid(cells));
  d.addCurve(surfaceCurve({{0.1f, 0.2f, 1.0f}, {0.5f, 0.5f, 1.0f}, {0.9f, 0.6f, 1.0f}}));
  d.addCurve(surfaceCurve({{1.0f, 0.1f, 0.2f}, {1.0f, 0.8f, 0.7f}}));
  return d;
}

}  // namespace

TEST(FieldDesigner, StraightCurveGivesANearlyConstantField) {
  FieldDesigner d(unitCube(), smallGrid());
  CurveUpdate u = d.addCurve(surfaceCurve({{0.1f, 0.3f, 1.0f}, {0.9f, 0.7f, 1.0f}}));
  EXPECT_TRUE(u.solve.converged);
  // Tangent (0.8, 0.4, 0) normalized is x, the face normal +z is z (canonical assignment).
  Frame expected;
  expected.x = Vec3f(0.8f, 0.4f, 0).normalized();
  expected.z = Vec3f::UnitZ();
  expected.y = expected.z.cross(expected.x);
  const Quatf target = expected.toQuaternion();
  float worst = 0;
  for (std::int64_t i = 0; i < d.grid().nodeCount(); ++i)
    worst = std::max(worst, rotationAngleDegrees(d.field().at(i), target));
  EXPECT_LT(worst, 0.1f);
  EXPECT_GE(d.field().at(d.constraints().front().first).w() * target.w() + 0.0f, -1.0f);  // sanity: finite
}

TEST(FieldDesigner, ConstraintsAreMetAtCurveNodes) {
  FieldDesigner d = twoCurveDesigner();
  d.addCurve(surfaceCurve({{0.2f, 1.0f, 0.2f}, {0.5f, 1.0f, 0.6f}, {0.8f, 1.0f, 0.7f}}, CurveMode::Align));
  float worst = 0, sum = 0;
  for (const auto& [node, target] : d.constraints()) {
    float angle = rotationAngleDegrees(d.field().at(node), target);
    worst = std::max(worst, angle);
    sum += angle;
  }
  const float mean = sum / float(d.constraints().size());
  RecordProperty("max_constraint_angle_deg", std::to_string(worst));
  RecordProperty("mean_constraint_angle_deg", std::to_string(mean));
  std::printf("constraint angle error over %zu nodes: mean %.4f deg, max %.4f deg\n", d.constraints().size(), mean,
              worst);
  // w = 100 makes the constraints nearly hard.
  EXPECT_LT(mean, 0.05f);
  EXPECT_LT(worst, 0.2f);
}

TEST(FieldDesigner, EverySampleIsAUnitQuaternion) {
  FieldDesigner d = twoCurveDesigner();
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coordinate(-0.2f, 1.2f);  // also outside the grid (clamped)
  for (int i = 0; i < 2000; ++i) {
    Quatf q = d.field().sample({coordinate(rng), coordinate(rng), coordinate(rng)});
    ASSERT_NEAR(q.norm(), 1.0f, 1e-5f);
  }
  for (const Quatf& q : d.field().rotations()) ASSERT_NEAR(q.norm(), 1.0f, 1e-5f);
}

TEST(FieldDesigner, SignFlipsOfInputFramesDoNotChangeTheField) {
  // The same frames given with random quaternion signs: the sign rules make them consistent.
  auto frames = [](bool flip) {
    std::vector<Vec3f> positions;
    std::vector<Quatf> rotations;
    std::mt19937 rng(11);
    for (int k = 0; k <= 20; ++k) {
      float t = float(k) / 20;
      positions.push_back({0.1f + 0.8f * t, 0.5f, 1.0f});
      Quatf q(Eigen::AngleAxisf(0.6f + t, Vec3f::UnitZ()));
      if (flip && (rng() & 1)) q.coeffs() *= -1;
      rotations.push_back(q);
    }
    return std::make_pair(positions, rotations);
  };
  FieldDesigner plain(unitCube(), smallGrid()), flipped(unitCube(), smallGrid());
  auto [p0, r0] = frames(false);
  auto [p1, r1] = frames(true);
  plain.addFrames(p0, r0);
  flipped.addFrames(p1, r1);
  // A second curve, drawn in opposite directions: refinement does not depend on orientation.
  SketchCurve side = surfaceCurve({{1.0f, 0.1f, 0.2f}, {1.0f, 0.8f, 0.7f}});
  plain.addCurve(side);
  std::reverse(side.points.begin(), side.points.end());
  flipped.addCurve(side);
  // Equal up to rounding (the reversed curve's samples are summed in another order).
  float mean = 0;
  for (std::int64_t i = 0; i < plain.grid().nodeCount(); ++i)
    mean += rotationAngleDegrees(plain.field().at(i), flipped.field().at(i));
  mean /= float(plain.grid().nodeCount());
  EXPECT_LT(mean, 1e-3f);
  EXPECT_LT(maxAngleDifference(plain.field(), flipped.field()), 0.01f);
}

TEST(FieldDesigner, ReversedAlignCurveGivesTheSameField) {
  FieldDesigner a = twoCurveDesigner(), b = twoCurveDesigner();
  SketchCurve top = surfaceCurve({{0.2f, 1.0f, 0.2f}, {0.5f, 1.0f, 0.6f}, {0.8f, 1.0f, 0.7f}}, CurveMode::Align);
  a.addCurve(top);
  std::reverse(top.points.begin(), top.points.end());
  b.addCurve(top);
  EXPECT_LT(maxAngleDifference(a.field(), b.field()), 0.05f);
}

TEST(FieldDesigner, AddingACurveChangesTheFieldMostlyNearIt) {
  FieldDesigner d = twoCurveDesigner(16);
  RotationField before = d.field();
  SketchCurve top = surfaceCurve({{0.1f, 1.0f, 0.1f}, {0.3f, 1.0f, 0.3f}}, CurveMode::Align);
  CurveUpdate u = d.addCurve(top);
  ASSERT_TRUE(u.solve.converged);
  const Vec3f centre(0.2f, 1.0f, 0.2f);
  double near = 0, far = 0;
  int nearCount = 0, farCount = 0;
  for (std::int64_t i = 0; i < d.grid().nodeCount(); ++i) {
    float change = rotationAngleDegrees(before.at(i), d.field().at(i));
    float distance = (d.grid().position(i) - centre).norm();
    if (distance < 0.25f) near += change, ++nearCount;
    if (distance > 0.75f) far += change, ++farCount;
  }
  near /= nearCount;
  far /= farCount;
  std::printf("mean change near the new curve %.2f deg, far from it %.2f deg\n", near, far);
  EXPECT_GT(near, 3 * far);
}

TEST(FieldDesigner, AlignCurveRotatesTheBestAxisOntoItsTangent) {
  FieldDesigner d = twoCurveDesigner();
  SketchCurve top = surfaceCurve({{0.2f, 1.0f, 0.2f}, {0.8f, 1.0f, 0.8f}}, CurveMode::Align);
  CurveUpdate u = d.addCurve(top);
  ASSERT_GE(u.alignedAxis, 0);
  const Vec3f tangent = Vec3f(1, 0, 1).normalized();
  for (const auto& [node, target] : d.constraints()) {
    Vec3f p = d.grid().position(node);
    if (p.y() < 0.99f || std::abs(p.x() - p.z()) > 0.05f || p.x() < 0.3f || p.x() > 0.7f) continue;
    Vec3f axis = d.field().at(node).toRotationMatrix().col(u.alignedAxis);
    EXPECT_GT(std::abs(axis.dot(tangent)), std::cos(3.0f * 3.14159265f / 180));
  }
}

TEST(FieldDesigner, IncrementalUpdateEqualsFullSolve) {
  FieldDesigner d = twoCurveDesigner(16);
  d.addCurve(surfaceCurve({{0.2f, 1.0f, 0.2f}, {0.5f, 1.0f, 0.6f}}, CurveMode::Align));
  RotationField full = d.solveFromScratch();
  float mean = 0;
  for (std::int64_t i = 0; i < d.grid().nodeCount(); ++i) mean += rotationAngleDegrees(d.field().at(i), full.at(i));
  mean /= float(d.grid().nodeCount());
  const float worst = maxAngleDifference(d.field(), full);
  std::printf("incremental vs full solve: mean %.4f deg, max %.4f deg\n", mean, worst);
  // Both stop at the solver tolerance (1e-4 relative step), from different starting points.
  EXPECT_LT(mean, 0.01f);
  EXPECT_LT(worst, 0.05f);
}

TEST(FieldDesigner, ResultDoesNotDependOnThreadCount) {
  RotationField many = twoCurveDesigner().field();
  RotationField one;
  {
    ThreadLimit limit(1);
    one = twoCurveDesigner().field();
  }
  for (std::int64_t i = 0; i < many.grid().nodeCount(); ++i) ASSERT_EQ(many.at(i).coeffs(), one.at(i).coeffs());
}

TEST(FieldDesigner, PlaneCurveUsesThePlaneNormal) {
  FieldDesigner d(unitCube(), smallGrid());
  SketchCurve c;
  c.placement = CurvePlacement::Plane;
  c.planeNormal = Vec3f(0, 1, 0);
  c.points = {{0.2f, 0.5f, 0.5f}, {0.8f, 0.5f, 0.5f}};
  d.addCurve(c);
  Frame f = d.field().frame({0.5f, 0.5f, 0.5f});
  EXPECT_GT(f.x.dot(Vec3f::UnitX()), 0.999f);  // tangent -> x
  EXPECT_GT(f.z.dot(Vec3f::UnitY()), 0.999f);  // plane normal -> z
}

TEST(FieldDesigner, RejectsBadCurvesAndOptions) {
  FieldDesigner d(unitCube(), smallGrid());
  test::expectInputError(
      [&] {
        d.addCurve(surfaceCurve({{0.5f, 0.5f, 3.0f}, {0.6f, 0.5f, 3.0f}}), "s.json");
      },
      "s.json", "from the mesh surface");
  test::expectInputError(
      [&] {
        d.addCurve(surfaceCurve({{0.1f, 0.5f, 1.0f}, {0.9f, 0.5f, 1.0f}}, CurveMode::Align), "s.json");
      },
      "s.json", "no field to refine");
  FieldDesignOptions bad = smallGrid();
  bad.solver.weight = -1;
  test::expectParameterError([&] { FieldDesigner(unitCube(), bad); }, "weight");
  bad.solver.weight = 1e6;  // beyond where the solver converges
  test::expectParameterError([&] { FieldDesigner(unitCube(), bad); }, "weight");
  bad = smallGrid(1);
  test::expectParameterError([&] { FieldDesigner(unitCube(), bad); }, "shortestCells");
}

// Undo in the studio: the field solved again from recorded targets, or the identity without any.
TEST(FieldDesigner, SetConstraintsSolvesFromTheGivenTargets) {
  FieldDesigner d = twoCurveDesigner();
  const RotationField before = d.field();
  const auto targets = d.constraints();
  d.setConstraints(targets);
  for (std::int64_t n = 0; n < d.grid().nodeCount(); n += 7)
    EXPECT_GT(std::abs(before.at(n).dot(d.field().at(n))), 0.9999f) << "node " << n;
  d.setConstraints({});
  EXPECT_FALSE(d.hasField());
  EXPECT_EQ(d.field().at(0).coeffs(), Quatf::Identity().coeffs());
  test::expectParameterError([&] { d.setConstraints({{-1, Quatf::Identity()}}); }, "targets");
  test::expectParameterError([&] { d.setConstraints({{0, Quatf(2, 0, 0, 0)}}); }, "targets");
}
