#include "texsynth/core/gradient_noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

TEST(GradientNoise, StaysInRangeAndUsesIt) {
  float lo2 = 0, hi2 = 0, lo3 = 0, hi3 = 0;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j) {
      float x = i * 0.173f - 17.0f, y = j * 0.131f - 9.0f;
      float n2 = gradientNoise2(x, y, 7), n3 = gradientNoise3(x, y, 0.37f * i - 0.11f * j, 7);
      lo2 = std::min(lo2, n2), hi2 = std::max(hi2, n2), lo3 = std::min(lo3, n3), hi3 = std::max(hi3, n3);
    }
  EXPECT_GE(lo2, -1.0f);
  EXPECT_LE(hi2, 1.0f);
  EXPECT_GE(lo3, -1.0f);
  EXPECT_LE(hi3, 1.0f);
  // Normalized: the range is actually used, not squeezed near 0.
  EXPECT_LT(lo2, -0.6f);
  EXPECT_GT(hi2, 0.6f);
  EXPECT_LT(lo3, -0.6f);
  EXPECT_GT(hi3, 0.6f);
}

TEST(GradientNoise, ZeroOnLatticeAndContinuous) {
  EXPECT_FLOAT_EQ(gradientNoise2(3, -4, 1), 0.0f);
  EXPECT_FLOAT_EQ(gradientNoise3(3, -4, 5, 1), 0.0f);
  const float h = 1e-3f;
  for (int k = 0; k < 500; ++k) {
    float x = k * 0.0371f - 5.0f, y = k * 0.0193f + 2.0f;
    // Lipschitz bound: the gradient magnitude of normalized Perlin noise is a few units.
    EXPECT_LT(std::abs(gradientNoise2(x + h, y, 3) - gradientNoise2(x, y, 3)), 10 * h);
    EXPECT_LT(std::abs(gradientNoise3(x, y + h, 0.5f, 3) - gradientNoise3(x, y, 0.5f, 3)), 10 * h);
  }
}

TEST(GradientNoise, PeriodicWhenAsked) {
  for (int k = 0; k < 100; ++k) {
    float x = k * 0.317f, y = k * 0.129f, z = k * 0.071f;
    EXPECT_NEAR(gradientNoise2(x, y, 5, 4, 6), gradientNoise2(x + 4, y - 6, 5, 4, 6), 1e-5);
    EXPECT_NEAR(gradientNoise3(x, y, z, 5, 4, 6, 3), gradientNoise3(x - 4, y + 6, z + 3, 5, 4, 6, 3), 1e-5);
  }
  // Without a period the same shift gives a different value.
  EXPECT_GT(std::abs(gradientNoise2(0.3f, 0.4f, 5) - gradientNoise2(4.3f, 0.4f, 5)), 1e-3f);
}

TEST(GradientNoise, SeedChangesTheNoiseDeterministically) {
  EXPECT_EQ(gradientNoise2(1.3f, 2.7f, 11), gradientNoise2(1.3f, 2.7f, 11));
  EXPECT_NE(gradientNoise2(1.3f, 2.7f, 11), gradientNoise2(1.3f, 2.7f, 12));
  EXPECT_NE(gradientNoise3(1.3f, 2.7f, 0.5f, 11), gradientNoise3(1.3f, 2.7f, 0.5f, 12));
}

TEST(GradientNoise, FbmInRangeAndValidated) {
  for (int k = 0; k < 300; ++k) {
    float v = fbm2(k * 0.21f, k * 0.07f, 2), w = fbm3(k * 0.21f, k * 0.07f, k * 0.03f, 2);
    EXPECT_LE(std::abs(v), 1.0f);
    EXPECT_LE(std::abs(w), 1.0f);
  }
  EXPECT_THROW(fbm2(0, 0, 1, {.octaves = 0}), ParameterError);
  EXPECT_THROW(fbm3(0, 0, 0, 1, {.lacunarity = -1}), ParameterError);
  EXPECT_THROW(fbm2(0, 0, 1, {.gain = NAN}), ParameterError);
}

}  // namespace
}  // namespace texsynth
