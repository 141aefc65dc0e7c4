// Grids, sampling, downsampling and the scale field.
#include <gtest/gtest.h>

#include "field_test_support.h"
#include "texsynth/field/harmonic_solver.h"

using namespace texsynth;

TEST(FieldGrid, CoversTheBoxWithCubicCellsAndMargin) {
  Box3f box;
  box.extend({0, 0, 0});
  box.extend({2, 1, 0.5f});
  FieldGridOptions options;
  options.shortestCells = 10;
  options.margin = 0.1f;
  FieldGrid g = makeFieldGrid(box, options);
  EXPECT_EQ(g.nodes.z(), 11);  // shortest side: 10 cells
  Box3f covered = g.bounds();
  EXPECT_LE(covered.min.x(), -0.2f + 1e-5f);
  EXPECT_GE(covered.max.x(), 2.2f - 1e-5f);
  EXPECT_NEAR(g.spacing * 10, 0.5f + 0.4f, 1e-5f);
  test::expectParameterError([&] { makeFieldGrid(box, {1, 0.1f}); }, "shortestCells");
  test::expectParameterError([&] { makeFieldGrid(box, {10, -0.1f}); }, "margin");
}

TEST(RotationField, SamplesNodesExactlyAndInterpolatesBetweenSigns) {
  FieldGrid g = makeFieldGrid(test::unitCube().bounds(), {4, 0});
  std::vector<Quatf> rotations;
  for (std::int64_t i = 0; i < g.nodeCount(); ++i) {
    Quatf q(Eigen::AngleAxisf(0.3f * float(g.coordinates(i).x()), Vec3f::UnitZ()));
    if (i % 2) q.coeffs() *= -1;  // stored signs must not matter
    rotations.push_back(q);
  }
  RotationField field(g, rotations);
  EXPECT_LT(rotationAngleDegrees(field.sample(g.position(7)), rotations[7]), 1e-3f);
  // Halfway between x = 1 and x = 2: the angle halfway between 0.3 and 0.6 rad.
  Vec3f mid = 0.5f * (g.position(1, 2, 2) + g.position(2, 2, 2));
  Quatf expected(Eigen::AngleAxisf(0.45f, Vec3f::UnitZ()));
  EXPECT_LT(rotationAngleDegrees(field.sample(mid), expected), 0.05f);
  test::expectParameterError([&] { RotationField(g, std::vector<Quatf>(3)); }, "rotations");
}

TEST(RotationField, DownsampledCopiesAreSmoothUnitFieldsOnHalfGrids) {
  FieldDesignOptions options = test::smallGrid(16);
  FieldDesigner d(test::unitCube(), options);
  d.addCurve(test::surfaceCurve({{0.1f, 0.2f, 1.0f}, {0.9f, 0.6f, 1.0f}}));
  d.addCurve(test::surfaceCurve({{1.0f, 0.1f, 0.2f}, {1.0f, 0.8f, 0.7f}}));
  std::vector<RotationField> levels = d.field().pyramid(2);
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_EQ(levels[1].grid().nodes, Vec3i(9, 9, 9));
  EXPECT_EQ(levels[2].grid().nodes, Vec3i(5, 5, 5));
  for (const RotationField& level : levels)
    for (const Quatf& q : level.rotations()) ASSERT_NEAR(q.norm(), 1.0f, 1e-5f);
  // A coarse level still says roughly what the fine one says.
  for (Vec3f p : {Vec3f(0.5f, 0.5f, 0.9f), Vec3f(0.9f, 0.5f, 0.5f), Vec3f(0.3f, 0.3f, 0.3f)})
    EXPECT_LT(rotationAngleDegrees(levels[0].sample(p), levels[1].sample(p)), 15.0f);
}

TEST(ScaleField, HarmonicInterpolationOfSparseScales) {
  FieldGrid g = makeFieldGrid(test::unitCube().bounds(), {12, 0});
  ScaleField s = interpolateScales(g, {{{0.1f, 0.5f, 0.5f}, 1.0f}, {{0.9f, 0.5f, 0.5f}, 4.0f}});
  EXPECT_NEAR(s.sample({0.1f, 0.5f, 0.5f}), 1.0f, 0.05f);
  EXPECT_NEAR(s.sample({0.9f, 0.5f, 0.5f}), 4.0f, 0.2f);
  float middle = s.sample({0.5f, 0.5f, 0.5f});
  EXPECT_GT(middle, 1.2f);
  EXPECT_LT(middle, 3.8f);
  for (float v : s.scales()) ASSERT_GT(v, 0.0f);
  EXPECT_EQ(interpolateScales(g, {}).sample({0.5f, 0.5f, 0.5f}), 1.0f);
  test::expectParameterError([&] { interpolateScales(g, {{{5, 5, 5}, 1.0f}}); }, "scalePoints");
  test::expectParameterError([&] { interpolateScales(g, {{{0.5f, 0.5f, 0.5f}, -1.0f}}); }, "scalePoints");
}

TEST(HarmonicSolver, OneConstraintGivesAConstantAndWarmStartsConverge) {
  FieldGrid g = makeFieldGrid(test::unitCube().bounds(), {8, 0});
  HarmonicSolver solver(g);
  FieldValues values;
  test::expectParameterError([&] { solver.solve(values); }, "constraints");
  solver.setConstraint(0, Eigen::Vector4d(1, 2, 3, 4));
  HarmonicSolveStats first = solver.solve(values);
  EXPECT_TRUE(first.converged);
  for (std::int64_t i = 0; i < g.nodeCount(); ++i)
    ASSERT_LT((values.row(i) - Eigen::RowVector4d(1, 2, 3, 4)).norm(), 1e-4);
  // Only a changed target: no new node, the warm start is already close.
  solver.setConstraint(0, Eigen::Vector4d(1, 2, 3, 4.01));
  HarmonicSolveStats second = solver.solve(values);
  EXPECT_TRUE(second.converged);
  EXPECT_LE(second.iterations, first.iterations + 2);
  test::expectParameterError([&] { solver.setConstraint(-1, Eigen::Vector4d::Zero()); }, "node");
}
