// evaluateImage: the four metrics on synthetic images, bad inputs, determinism.
#include "texsynth/eval/metrics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "eval_test_images.h"
#include "test_support.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

using test::makeTestPattern;

TEST(EvaluateImage, IdenticalOutputScoresZero) {
  Image exemplar = makeTestPattern(64, 64);
  QualityMetrics m = evaluateImage(exemplar, exemplar);
  EXPECT_EQ(m.coherence, 0.0);
  EXPECT_EQ(m.completeness, 0.0);
  EXPECT_EQ(m.histogram, 0.0);
  EXPECT_LT(m.periodicity, 0.05);
  EXPECT_GE(m.seconds, 0.0);
}

TEST(EvaluateImage, NoiseScoresWorseThanAShiftedCrop) {
  Image big = makeTestPattern(80, 80, 4);
  Image exemplar = big.crop(0, 0, 48, 48);
  QualityMetrics shifted = evaluateImage(exemplar, big.crop(14, 9, 48, 48));
  QualityMetrics noisy = evaluateImage(exemplar, test::noise(48, 48, 8));
  EXPECT_GT(shifted.coherence, 0.0);
  EXPECT_GT(noisy.coherence, 2 * shifted.coherence);
  EXPECT_GT(noisy.completeness, 2 * shifted.completeness);
  EXPECT_GT(noisy.histogram, shifted.histogram);
}

TEST(EvaluateImage, TheCoherenceTailSeesASeamTheMeanHides) {
  Image big = makeTestPattern(120, 120, 4);
  const Image exemplar = big.crop(0, 0, 64, 64);
  EXPECT_EQ(evaluateImage(exemplar, exemplar).coherenceTail, 0.0);
  // Two crops of the same texture joined along a vertical cut: only the patches across the cut
  // (6 of 58 columns of patch positions) are off.
  Image seamed = big.crop(0, 0, 64, 64);
  const Image other = big.crop(37, 21, 64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 32; x < 64; ++x)
      for (int c = 0; c < seamed.channels; ++c) seamed.at(x, y, c) = other.at(x, y, c);
  const QualityMetrics m = evaluateImage(exemplar, seamed);
  EXPECT_GT(m.coherenceTail, 0.0);
  EXPECT_GT(m.coherenceTail, 1.3 * m.coherence) << "the tail " << m.coherenceTail << ", the mean " << m.coherence;
  // Noise: every patch is about as far off, the tail is near the mean.
  const QualityMetrics noisy = evaluateImage(exemplar, test::noise(64, 64, 8));
  EXPECT_LT(noisy.coherenceTail, 1.2 * noisy.coherence)
      << "the tail " << noisy.coherenceTail << ", the mean " << noisy.coherence;
}

TEST(EvaluateImage, ShiftOfTenIsHistogramTen) {
  Image exemplar = test::scaled(makeTestPattern(48, 48), 235.0f / 255.0f);
  Image output = exemplar;
  for (float& v : output.pixels) v += 10.0f / 255.0f;
  QualityMetrics m = evaluateImage(exemplar, output);
  EXPECT_NEAR(m.histogram, 10.0, 1e-3);
  // Every patch is off by exactly 10 per value, and its own position is the nearest.
  EXPECT_NEAR(m.coherence, 10.0, 1e-3);
  EXPECT_NEAR(m.completeness, 10.0, 1e-3);
}

TEST(EvaluateImage, TilingIsPeriodicACropIsNot) {
  Image exemplar = makeTestPattern(64, 64, 6);
  QualityMetrics tiling = evaluateImage(exemplar, exemplar.tiled(160, 160));
  EXPECT_GT(tiling.periodicity, 0.5);
  EXPECT_LT(tiling.completeness, 1e-9);  // every exemplar patch appears in the tiling
  // A crop of a larger texture is the ideal "synthesis": it never repeats.
  Image big = makeTestPattern(160, 160, 6);
  EXPECT_LT(evaluateImage(big.crop(0, 0, 64, 64), big.crop(20, 10, 140, 150)).periodicity, 0.05);
}

TEST(EvaluateImage, ConvertsChannelCounts) {
  Image gray = makeTestPattern(32, 32).withChannels(1);
  Image rgba = gray.withChannels(4);
  QualityMetrics m = evaluateImage(gray, rgba);  // both become the same RGB image
  EXPECT_EQ(m.coherence, 0.0);
  EXPECT_EQ(m.histogram, 0.0);
}

TEST(EvaluateImage, SameMetricsForAnyThreadCount) {
  Image big = makeTestPattern(140, 120, 11);
  Image exemplar = big.crop(0, 0, 70, 60);
  Image output = big.crop(30, 40, 100, 80);
  QualityMetrics one, two;
  {
    ThreadLimit limit(1);
    one = evaluateImage(exemplar, output);
  }
  {
    ThreadLimit limit(2);
    two = evaluateImage(exemplar, output);
  }
  EXPECT_EQ(one.coherence, two.coherence);
  EXPECT_EQ(one.completeness, two.completeness);
  EXPECT_EQ(one.histogram, two.histogram);
  EXPECT_EQ(one.periodicity, two.periodicity);
}

// The ParameterError's parameter, or "" if `call` did not throw one.
template <typename F>
std::string rejectedParameter(F call) {
  try {
    call();
  } catch (const ParameterError& e) {
    return e.parameter();
  }
  return "";
}

TEST(EvaluateImage, RejectsBadInput) {
  Image good = makeTestPattern(16, 16);
  EXPECT_EQ(rejectedParameter([&] { evaluateImage(makeTestPattern(6, 16), good); }), "exemplar");
  EXPECT_EQ(rejectedParameter([&] { evaluateImage(good, makeTestPattern(16, 5)); }), "output");
  EXPECT_EQ(rejectedParameter([&] { evaluateImage(Image(), good); }), "exemplar");
  Image nan = good;
  nan.at(3, 4, 1) = std::nanf("");
  EXPECT_EQ(rejectedParameter([&] { evaluateImage(good, nan); }), "output");
  auto withOptions = [&](MetricOptions options) {
    return rejectedParameter([&] { evaluateImage(good, good, options); });
  };
  EXPECT_EQ(withOptions({.patchSize = 6}), "patchSize");
  EXPECT_EQ(withOptions({.patchSize = 0}), "patchSize");
  EXPECT_EQ(withOptions({.periodicitySamples = 0}), "periodicitySamples");
  EXPECT_EQ(withOptions({.duplicateThreshold = -1}), "duplicateThreshold");
  EXPECT_EQ(withOptions({.slicesPerAxis = 0}), "slicesPerAxis");
  // A patch as large as the image is fine: one patch each.
  EXPECT_EQ(evaluateImage(good, good, {.patchSize = 15}).coherence, 0.0);
}

}  // namespace
}  // namespace texsynth
