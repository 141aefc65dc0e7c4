// Wasserstein-1 distances of value distributions.
#include "texsynth/eval/histogram_distance.h"

#include <gtest/gtest.h>

#include "eval_test_images.h"
#include "test_support.h"

namespace texsynth {
namespace {

TEST(Wasserstein1, KnownValues) {
  EXPECT_DOUBLE_EQ(wasserstein1({0.0f}, {1.0f}), 1.0);
  EXPECT_DOUBLE_EQ(wasserstein1({0, 1}, {1, 0, 0, 1}), 0.0);       // same distribution, other size
  EXPECT_NEAR(wasserstein1({0, 1, 2}, {0, 2}), 1.0 / 3.0, 1e-12);  // |1/3-1/2| + |2/3-1/2|
  EXPECT_DOUBLE_EQ(wasserstein1({3, 1, 2}, {5, 6, 4}), 3.0);       // order does not matter
  EXPECT_NEAR(wasserstein1({0, 0, 0, 10}, {0}), 2.5, 1e-12);
}

TEST(Wasserstein1, RejectsEmptySamples) {
  EXPECT_THROW(wasserstein1({}, {1.0f}), ParameterError);
  EXPECT_THROW(wasserstein1({1.0f}, {}), ParameterError);
}

TEST(HistogramDistance, ConstantShiftIsTheShift) {
  Image a = test::scaled(test::makeTestPattern(40, 30), 200);
  Image b = a;
  for (float& v : b.pixels) v += 10;
  EXPECT_NEAR(histogramDistance(a, b), 10.0, 1e-4);
  EXPECT_NEAR(histogramDistance(b, a), 10.0, 1e-4);
  EXPECT_EQ(histogramDistance(a, a), 0.0);
}

TEST(HistogramDistance, IgnoresPixelPositionsButNotValues) {
  Image a = test::makeTestPattern(32, 32);
  Image mirrored = a;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) mirrored.at(x, y, c) = a.at(31 - x, y, c);
  EXPECT_NEAR(histogramDistance(a, mirrored), 0.0, 1e-12);
  EXPECT_GT(histogramDistance(a, test::noise(32, 32, 1)), 0.01);
}

TEST(HistogramDistance, RejectsMismatchedImages) {
  EXPECT_THROW(histogramDistance(Image(4, 4, 3), Image(4, 4, 1)), ParameterError);
  EXPECT_THROW(histogramDistance(Image(), Image(4, 4, 3)), ParameterError);
}

}  // namespace
}  // namespace texsynth
