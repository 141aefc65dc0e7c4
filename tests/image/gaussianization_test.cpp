#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/image/histogram_gaussianization.h"
#include "texsynth/image/triangle_grid.h"

namespace texsynth {
namespace {

TEST(Gaussianization, InverseNormalCdf) {
  EXPECT_NEAR(inverseNormalCdf(0.5), 0.0, 1e-12);
  EXPECT_NEAR(inverseNormalCdf(0.975), 1.959963984540054, 1e-9);
  EXPECT_NEAR(inverseNormalCdf(1e-6), -4.753424308822899, 1e-8);
  EXPECT_THROW(inverseNormalCdf(0.0), ParameterError);
}

TEST(Gaussianization, GaussianHasStandardMoments) {
  Image exemplar = test::makeTestPattern(64, 48);
  GaussianizedExemplar g = gaussianize(exemplar);
  ASSERT_EQ(g.gaussian.width, 64);
  ASSERT_EQ(g.gaussian.channels, exemplar.channels);
  for (int c = 0; c < exemplar.channels; ++c) {
    double sum = 0, sumSquares = 0;
    for (std::size_t p = 0; p < g.gaussian.pixelCount(); ++p) {
      double v = g.gaussian.pixels[p * exemplar.channels + c];
      sum += v, sumSquares += v * v;
    }
    double n = double(g.gaussian.pixelCount()), mean = sum / n;
    EXPECT_NEAR(mean, 0.0, 1e-6);
    EXPECT_NEAR(sumSquares / n - mean * mean, 1.0, 0.01);
  }
}

TEST(Gaussianization, RoundTripRestoresValues) {
  Image exemplar = test::makeTestPattern(64, 64, 3);
  GaussianizedExemplar g = gaussianize(exemplar);
  Image back = g.toColor(g.gaussian);
  double maxError = 0;
  for (std::size_t i = 0; i < back.pixels.size(); ++i)
    maxError = std::max(maxError, double(std::abs(back.pixels[i] - exemplar.pixels[i])));
  // 1024 entries over ±4: a step holds a handful of ranks, so T⁻¹(T(v)) lands within a few
  // neighbouring exemplar values.
  EXPECT_LT(maxError, 0.05);
  double meanError = 0;
  for (std::size_t i = 0; i < back.pixels.size(); ++i) meanError += std::abs(back.pixels[i] - exemplar.pixels[i]);
  EXPECT_LT(meanError / double(back.pixels.size()), 0.005);
}

TEST(Gaussianization, LutIsMonotoneAndClampsOutsideItsRange) {
  GaussianizedExemplar g = gaussianize(test::makeTestPattern(32, 32));
  for (int c = 0; c < g.lut.channels(); ++c) {
    for (float x = -5; x < 5; x += 0.01f) EXPECT_LE(g.lut.lookup(c, x), g.lut.lookup(c, x + 0.01f));
    EXPECT_EQ(g.lut.lookup(c, -100.0f), g.lut.lookup(c, -4.0f));
    EXPECT_EQ(g.lut.lookup(c, 100.0f), g.lut.lookup(c, 4.0f));
  }
}

TEST(Gaussianization, RejectsBadInput) {
  EXPECT_THROW(gaussianize(Image()), ParameterError);
  EXPECT_THROW(gaussianize(test::makeTestPattern(8, 8), {.lutSize = 1}), ParameterError);
  EXPECT_THROW(gaussianize(test::makeTestPattern(8, 8), {.gaussianRange = 0}), ParameterError);
  EXPECT_THROW(gaussianize(test::makeTestPattern(8, 8), {.gaussianRange = INFINITY}), ParameterError);
}

TEST(TriangleGrid, WeightsAreBarycentricAndVerticesEnclose) {
  for (int k = 0; k < 1000; ++k) {
    double x = k * 0.0731 - 20, y = k * 0.0417 - 11;
    GridTriangle t = triangleGridLookup(x, y);
    double sum = 0, px = 0, py = 0;
    for (int v = 0; v < 3; ++v) {
      EXPECT_GE(t.weight[v], -1e-6f);
      sum += t.weight[v];
      // Lattice vertex (i, j) sits at i (1, 0) + j (1/2, sqrt(3)/2).
      px += t.weight[v] * (t.vertexI[v] + 0.5 * t.vertexJ[v]);
      py += t.weight[v] * (t.vertexJ[v] * std::sqrt(3.0) / 2);
    }
    EXPECT_NEAR(sum, 1.0, 1e-5);
    EXPECT_NEAR(px, x, 1e-4);  // barycentric weights reproduce the point
    EXPECT_NEAR(py, y, 1e-4);
  }
}

TEST(TriangleGrid, VarianceBlendKeepsVarianceOfGaussians) {
  // Blend three independent unit-variance sequences with fixed weights: variance stays 1.
  const float weights[3] = {0.5f, 0.3f, 0.2f};
  double sumSquares = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    float a = float(inverseNormalCdf((i + 0.5) / n));
    float b = float(inverseNormalCdf(((i * 7919) % n + 0.5) / n));
    float c = float(inverseNormalCdf(((i * 104729) % n + 0.5) / n));
    const float* values[3] = {&a, &b, &c};
    float out;
    varianceBlend(values, weights, 3, 1, 0.0f, &out);
    sumSquares += out * out;
  }
  EXPECT_NEAR(sumSquares / n, 1.0, 0.05);
  float w[3] = {0.6f, 0.3f, 0.1f};
  sharpenWeights(w, 3, 2.0f);
  EXPECT_NEAR(w[0] + w[1] + w[2], 1.0f, 1e-6f);
  EXPECT_GT(w[0], 0.6f);
}

}  // namespace
}  // namespace texsynth
