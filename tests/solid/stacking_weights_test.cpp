#include <gtest/gtest.h>

#include "solid_test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/solid/tile_deform_solid.h"

using namespace texsynth;

TEST(StackingWeights, SumToOneForAnyNormal) {
  for (const Vec3f& n : test::randomNormals(200))
    for (float p : {0.5f, 1.0f, 4.0f, 32.0f}) {
      Vec3f w = stackingWeights(n, p);
      EXPECT_NEAR(w.sum(), 1.0f, 1e-5f);
      EXPECT_GE(w.minCoeff(), 0.0f);
    }
}

TEST(StackingWeights, AxisAlignedNormalPicksOneAxis) {
  for (int axis = 0; axis < 3; ++axis) {
    Vec3f n = Vec3f::Zero();
    n[axis] = axis == 1 ? -1.0f : 1.0f;  // the sign of the normal does not matter
    Vec3f expected = Vec3f::Zero();
    expected[axis] = 1.0f;
    EXPECT_EQ(stackingWeights(n, 4.0f), expected);
  }
}

TEST(StackingWeights, FollowsEquation3) {
  const Vec3f n = Vec3f(0.8f, 0.6f, 0.0f);
  const Vec3f w = stackingWeights(n, 1.0f);  // (0.64, 0.36, 0) already sums to 1
  EXPECT_NEAR(w.x(), 0.64f, 1e-6f);
  EXPECT_NEAR(w.y(), 0.36f, 1e-6f);
  EXPECT_EQ(w.z(), 0.0f);
}

TEST(StackingWeights, HigherPIsSharper) {
  const Vec3f n = Vec3f(0.7f, 0.5f, 0.3f).normalized();
  float previous = 0;
  for (float p : {0.5f, 1.0f, 2.0f, 4.0f, 16.0f}) {
    float dominant = stackingWeights(n, p).x();
    EXPECT_GT(dominant, previous) << "p = " << p;
    previous = dominant;
  }
  EXPECT_GT(previous, 0.99f);
}

TEST(StackingWeights, NoNormalGivesEqualWeights) {
  EXPECT_EQ(stackingWeights(Vec3f::Zero(), 4.0f), Vec3f::Constant(1.0f / 3.0f));
  const Vec3f diagonal = Vec3f::Ones().normalized();
  EXPECT_TRUE(stackingWeights(diagonal, 4.0f).isApprox(Vec3f::Constant(1.0f / 3.0f), 1e-5f));
}

TEST(StackingWeights, BadSharpnessRejected) {
  for (float p : {0.0f, -1.0f, 65.0f, std::nanf("")}) {
    try {
      validateBlendSharpness(p);
      ADD_FAILURE() << "accepted p = " << p;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.parameter(), "blendSharpness");
    }
  }
}
