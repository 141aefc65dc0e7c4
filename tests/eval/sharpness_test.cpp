// Sharpness: a blurred copy scores below the original, the original scores 1 against itself.
#include "texsynth/eval/sharpness.h"

#include <gtest/gtest.h>

#include "test_support.h"
#include "texsynth/eval/metrics.h"

namespace texsynth {
namespace {

// A 3x3 box blur (wrapping at the borders).
Image boxBlur(const Image& image) {
  Image out(image.width, image.height, image.channels);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < image.channels; ++c) {
        float sum = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            sum += image.at((x + dx + image.width) % image.width, (y + dy + image.height) % image.height, c);
        out.pixel(x, y)[c] = sum / 9;
      }
  return out;
}

TEST(Sharpness, FlatIsZeroAndARampIsItsSlope) {
  EXPECT_EQ(meanGradientMagnitude(Image(8, 8, 3)), 0.0);
  EXPECT_EQ(meanGradientMagnitude(Image(1, 8, 3)), 0.0);
  Image ramp(8, 4, 1);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) ramp.pixel(x, y)[0] = 0.5f * x;
  EXPECT_NEAR(meanGradientMagnitude(ramp), 0.5, 1e-9);
}

TEST(Sharpness, BlurScoresBelowTheExemplarAndACopyScoresOne) {
  Image exemplar = test::makeTestPattern(48, 48);
  MetricOptions options{.periodicitySamples = 200};
  EXPECT_NEAR(evaluateImage(exemplar, exemplar, options).sharpness, 1.0, 1e-9);
  const double blurred = evaluateImage(exemplar, boxBlur(exemplar), options).sharpness;
  EXPECT_LT(blurred, 0.8);
  EXPECT_GT(blurred, 0.0);
}

}  // namespace
}  // namespace texsynth
