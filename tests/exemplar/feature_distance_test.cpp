#include "texsynth/exemplar/feature_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "exemplar_test_util.h"
#include "texsynth/core/error.h"
#include "texsynth/core/random.h"

using namespace texsynth;

namespace {

// Brute-force toroidal distance from (x, y) to the nearest pixel whose mask state is `target`.
float bruteDistance(const Image& mask, int x, int y, bool target) {
  float best = std::numeric_limits<float>::infinity();
  for (int v = 0; v < mask.height; ++v)
    for (int u = 0; u < mask.width; ++u) {
      if ((mask.at(u, v, 0) != 0.0f) != target) continue;
      int dx = std::abs(u - x), dy = std::abs(v - y);
      dx = std::min(dx, mask.width - dx);
      dy = std::min(dy, mask.height - dy);
      best = std::min(best, std::sqrt(float(dx * dx + dy * dy)));
    }
  return best;
}

void expectExact(const Image& mask) {
  Image sdf = signedDistanceToFeature(mask);
  ASSERT_EQ(sdf.channels, 1);
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      bool feature = mask.at(x, y, 0) != 0.0f;
      float expected = feature ? -bruteDistance(mask, x, y, false) : bruteDistance(mask, x, y, true);
      ASSERT_NEAR(sdf.at(x, y, 0), expected, 1e-5f) << "at " << x << "," << y;
    }
}

}  // namespace

TEST(FeatureDistance, SinglePixelGivesToroidalEuclideanDistance) {
  Image mask(16, 12, 1);
  mask.at(3, 4, 0) = 1.0f;
  Image sdf = signedDistanceToFeature(mask);
  EXPECT_FLOAT_EQ(sdf.at(3, 4, 0), -1.0f);                       // inside: one step to the background
  EXPECT_FLOAT_EQ(sdf.at(6, 8, 0), 5.0f);                        // 3-4-5 triangle
  EXPECT_FLOAT_EQ(sdf.at(15, 4, 0), 4.0f);                       // wraps: 3 - (-1)
  EXPECT_FLOAT_EQ(sdf.at(3, 11, 0), 5.0f);                       // wraps: 4 - (-1)
  EXPECT_FLOAT_EQ(sdf.at(11, 10, 0), std::sqrt(64.0f + 36.0f));  // farthest point on the torus
  expectExact(mask);
}

TEST(FeatureDistance, MatchesBruteForceOnBlobsAndNoise) {
  expectExact(test::makeBlobMask(23, 17));
  Image noise(19, 21, 1);
  for (std::size_t p = 0; p < noise.pixelCount(); ++p) noise.pixels[p] = uniform01(hashKey(5, p)) < 0.08f ? 1.f : 0.f;
  expectExact(noise);
}

TEST(FeatureDistance, AnyNonzeroChannelIsFeature) {
  Image mask(8, 8, 3);
  mask.at(2, 2, 2) = 0.5f;
  Image sdf = signedDistanceToFeature(mask);
  EXPECT_FLOAT_EQ(sdf.at(2, 2, 0), -1.0f);
  EXPECT_FLOAT_EQ(sdf.at(2, 5, 0), 3.0f);
}

TEST(FeatureDistance, ChannelIsNormalizedAndWeighted) {
  Image mask = test::makeBlobMask(24, 24);
  Image channel = featureChannelFromMask(mask, 0.5f);
  float largest = 0, smallest = 0;
  for (float v : channel.pixels) {
    largest = std::max(largest, v);
    smallest = std::min(smallest, v);
  }
  EXPECT_FLOAT_EQ(std::max(largest, -smallest), 0.5f);
  EXPECT_LT(smallest, 0.0f);
  EXPECT_GT(largest, 0.0f);
}

TEST(FeatureDistance, RejectsDegenerateMasks) {
  EXPECT_THROW(signedDistanceToFeature(Image(8, 8, 1, 0.0f)), ParameterError);
  EXPECT_THROW(signedDistanceToFeature(Image(8, 8, 1, 1.0f)), ParameterError);
  EXPECT_THROW(signedDistanceToFeature(Image()), ParameterError);
  EXPECT_THROW(featureChannelFromMask(test::makeBlobMask(8, 8), -1.0f), ParameterError);
  EXPECT_THROW(appendChannel(Image(8, 8, 3), Image(8, 9, 1)), ParameterError);
}
