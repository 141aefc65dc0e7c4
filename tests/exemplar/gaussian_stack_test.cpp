#include "texsynth/exemplar/gaussian_stack.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"
#include "texsynth/core/error.h"

using namespace texsynth;

namespace {

double channelMean(const Image& image, int c) {
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum / double(image.pixelCount());
}

double channelVariance(const Image& image, int c) {
  double mean = channelMean(image, c), sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += (image.at(x, y, c) - mean) * (image.at(x, y, c) - mean);
  return sum / double(image.pixelCount());
}

}  // namespace

TEST(GaussianStack, DefaultLevelsAndSpacings) {
  Image exemplar = test::makeTestPattern(64, 48);
  GaussianStack stack = buildGaussianStack(exemplar);
  ASSERT_EQ(stack.levelCount(), 5);  // floor(log2(48))
  EXPECT_EQ(stack.spacing(0), 16);
  EXPECT_EQ(stack.spacing(4), 1);
  for (const Image& level : stack.levels) {
    EXPECT_EQ(level.width, 64);
    EXPECT_EQ(level.height, 48);
    EXPECT_EQ(level.channels, 3);
  }
  EXPECT_EQ(stack.levels.back().pixels, exemplar.pixels);  // finest level is the exemplar
  EXPECT_EQ(defaultStackLevelCount(128, 128), 7);
  EXPECT_EQ(defaultStackLevelCount(1, 1), 1);
}

TEST(GaussianStack, PreservesMeanAndSmoothsMonotonically) {
  Image exemplar = test::makeTestPattern(64, 64, 7);
  GaussianStack stack = buildGaussianStack(exemplar);
  for (int c = 0; c < 3; ++c) {
    double mean = channelMean(exemplar, c);
    double previousVariance = channelVariance(exemplar, c);
    for (int level = stack.levelCount() - 2; level >= 0; --level) {
      EXPECT_NEAR(channelMean(stack.levels[level], c), mean, 1e-5) << "level " << level;
      double variance = channelVariance(stack.levels[level], c);
      EXPECT_LT(variance, previousVariance) << "level " << level << " channel " << c;
      previousVariance = variance;
    }
  }
}

TEST(GaussianStack, DilatedBinomialKernelWrapsAround) {
  Image impulse(16, 10, 1);
  impulse.at(0, 0, 0) = 1.0f;
  Image filtered = filterBinomialToroidal(impulse, 2);
  // Separable [1 4 6 4 1]/16 at taps 0, +-2, +-4, wrapping over the left and top borders.
  const float weights[5] = {1.f / 16, 4.f / 16, 6.f / 16, 4.f / 16, 1.f / 16};
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i)
      EXPECT_NEAR(filtered.wrapped(2 * i, 2 * j, 0), weights[i + 2] * weights[j + 2], 1e-7) << i << "," << j;
  EXPECT_EQ(filtered.at(1, 0, 0), 0.0f);  // between the taps
  double total = 0;
  for (float v : filtered.pixels) total += v;
  EXPECT_NEAR(total, 1.0, 1e-6);
}

TEST(GaussianStack, ExplicitLevelCount) {
  Image exemplar = test::makeTestPattern(32, 32);
  GaussianStack stack = buildGaussianStack(exemplar, {3});
  ASSERT_EQ(stack.levelCount(), 3);
  EXPECT_EQ(stack.spacing(0), 4);
}

TEST(GaussianStack, RejectsBadParameters) {
  Image exemplar = test::makeTestPattern(32, 32);
  EXPECT_THROW(buildGaussianStack(exemplar, {6}), ParameterError);  // 2^5 spacing > half of 32
  EXPECT_THROW(buildGaussianStack(exemplar, {-1}), ParameterError);
  EXPECT_THROW(buildGaussianStack(Image()), ParameterError);
}
