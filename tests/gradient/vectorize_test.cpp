// Vectorization: the signed distance, first-order and optimized fits, regions, detail, determinism.
#include "texsynth/gradient/vectorize.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/gradient/tricubic_basis.h"

namespace texsynth {
namespace {

// A smooth RGB volume: slow waves of different phases per channel.
Volume smoothVolume(int n) {
  Volume volume(n, n, n, 3);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int c = 0; c < 3; ++c)
          volume.at(x, y, z, c) =
              0.5f + 0.4f * std::sin(0.11f * x + 0.07f * y * (c + 1) + 0.05f * z + c) * std::cos(0.09f * z - 0.3f * c);
  return volume;
}

// A ball of radius r: dark red inside on a smooth green-blue outside; its mask.
std::pair<Volume, Volume> ballVolume(int n, float r) {
  Volume volume(n, n, n, 3), mask(n, n, n, 1);
  const float centre = 0.5f * (n - 1) + 0.3f;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const bool inside = Vec3f(x - centre, y - centre, z - centre).norm() < r;
        mask.at(x, y, z, 0) = inside ? 1.0f : 0.0f;
        const float shade = 0.5f + 0.01f * float(x + y);
        volume.at(x, y, z, 0) = inside ? 0.8f * shade : 0.1f;
        volume.at(x, y, z, 1) = inside ? 0.1f : 0.6f * shade;
        volume.at(x, y, z, 2) = inside ? 0.2f : 0.9f - 0.3f * shade;
      }
  return {volume, mask};
}

TEST(SignedDistance, MatchesBruteForce) {
  Volume mask(12, 9, 7, 1);
  for (int z = 0; z < 7; ++z)
    for (int y = 0; y < 9; ++y)
      for (int x = 0; x < 12; ++x) mask.at(x, y, z, 0) = (x * 7 + y * 3 + z * 5) % 11 < 3 || x > 8 ? 1.0f : 0.0f;
  const Volume distance = signedDistanceVolume(mask, 100.0f);
  for (int z = 0; z < 7; ++z)
    for (int y = 0; y < 9; ++y)
      for (int x = 0; x < 12; ++x) {
        const bool inside = mask.at(x, y, z, 0) > 0.5f;
        float nearest = 1e9f;
        for (int w = 0; w < 7; ++w)
          for (int v = 0; v < 9; ++v)
            for (int u = 0; u < 12; ++u)
              if ((mask.at(u, v, w, 0) > 0.5f) != inside)
                nearest = std::min(nearest, Vec3f(float(u - x), float(v - y), float(w - z)).norm());
        EXPECT_NEAR(distance.at(x, y, z, 0), inside ? nearest - 0.5f : 0.5f - nearest, 1e-4f);
      }
}

TEST(Vectorize, FitsSmoothVolumesAndOptimizationLowersTheError) {
  const Volume volume = smoothVolume(48);
  VectorizeOptions options;
  options.quantize = false;
  VectorizeReport first, optimized;
  const GradientSolid solid = vectorizeVolume(volume, {}, options, &first);
  EXPECT_EQ(solid.controls, Vec3i(13, 13, 13));
  options.optimize = true;
  vectorizeVolume(volume, {}, options, &optimized);
  EXPECT_LT(first.rms, 1.5);
  EXPECT_LT(optimized.rms, 0.6 * first.rms);
  EXPECT_NEAR(gradientSolidRms(solid, volume), first.rms, 1e-9);
}

TEST(Vectorize, OptimizationReproducesAVolumeItCanRepresent) {
  // Sampled from a sum of per-axis cubics: the optimum of eq. 3 is exact.
  Volume volume(30, 27, 22, 1);
  for (int z = 0; z < 22; ++z)
    for (int y = 0; y < 27; ++y)
      for (int x = 0; x < 30; ++x)
        volume.at(x, y, z, 0) = 0.2f + 1e-2f * x - 3e-5f * x * x * x + 2e-4f * y * y + 0.3f * std::pow(z / 22.0f, 3.0f);
  VectorizeOptions options;
  options.quantize = false;
  options.optimize = true;
  options.iterations = 200;
  VectorizeReport report;
  vectorizeVolume(volume, {}, options, &report);
  EXPECT_LT(report.rms, 0.02);
}

TEST(Vectorize, SeparatesRegionsAlongTheMask) {
  const auto [volume, mask] = ballVolume(40, 11.0f);
  VectorizeOptions options;
  options.optimize = true;
  VectorizeReport regions, plain;
  const GradientSolid solid = vectorizeVolume(volume, mask, options, &regions);
  vectorizeVolume(volume, {}, options, &plain);
  EXPECT_TRUE(solid.hasRegions());
  EXPECT_GT(regions.boundaryControls, 0);
  EXPECT_LT(regions.rms, 0.5 * plain.rms) << "sharp boundaries need the two regions";
  int agree = 0, total = 0;
  for (int z = 0; z < 40; ++z)
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x, ++total)
        agree +=
            (evaluateGradientDistance(solid, Vec3f(float(x), float(y), float(z))) > 0) == (mask.at(x, y, z, 0) > 0.5f);
  EXPECT_GT(double(agree) / total, 0.995);
}

TEST(Vectorize, DetailSigmaFollowsTheResidual) {
  Volume volume = smoothVolume(32);
  for (std::size_t n = 0; n < volume.voxels.size(); ++n)  // grain of deviation ~0.04 on the smooth field
    volume.voxels[n] += 0.04f * (2.0f * float((n * 2654435761u) % 1000) / 999.0f - 1.0f) * 1.7320508f;
  VectorizeOptions options;
  options.detail = true;
  const GradientSolid solid = vectorizeVolume(volume, {}, options);
  ASSERT_TRUE(solid.hasDetail());
  double sigma = 0;
  for (std::size_t n = 0; n < solid.detail.size(); n += 12) sigma += solid.detail[n];
  sigma /= double(solid.detail.size() / 12);
  EXPECT_NEAR(sigma, 0.04, 0.01);
}

TEST(Vectorize, IsDeterministicAcrossThreadCounts) {
  const auto [volume, mask] = ballVolume(36, 9.0f);
  VectorizeOptions options;
  options.optimize = true;
  options.detail = true;
  GradientSolid one, all;
  {
    ThreadLimit limit(1);
    one = vectorizeVolume(volume, mask, options);
  }
  all = vectorizeVolume(volume, mask, options);
  EXPECT_EQ(one.positive, all.positive);
  EXPECT_EQ(one.negative, all.negative);
  EXPECT_EQ(one.distance, all.distance);
  EXPECT_EQ(one.detail, all.detail);
}

// The weight table with trilinear lookups (§5.3) against the exact weights, on vectorized solids: a
// smooth one and one with sharp regions.
TEST(Vectorize, TableEvaluationIsWithinOneLevelOfExact) {
  const auto [balls, mask] = ballVolume(40, 11.0f);
  const GradientSolid solids[2] = {vectorizeVolume(smoothVolume(40), {}), vectorizeVolume(balls, mask)};
  for (int samples : {33, 17}) {
    const TricubicWeightTable table(samples);
    GradientEvaluateOptions tabled;
    tabled.table = &table;
    for (const GradientSolid& solid : solids) {
      float worst = 0;
      for (int n = 0; n < 50000; ++n) {
        const Vec3f p(uniform01(hashKey(7, n)) * 39, uniform01(hashKey(8, n)) * 39, uniform01(hashKey(9, n)) * 39);
        // Right on a region boundary the table's distance may pick the other side: a whole colour step.
        if (solid.hasRegions() && std::abs(evaluateGradientDistance(solid, p)) < 0.02f) continue;
        float exact[4], approximate[4];
        evaluateGradientSolid(solid, p, {}, exact);
        evaluateGradientSolid(solid, p, tabled, approximate);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(exact[c] - approximate[c]));
      }
      EXPECT_LT(worst, 1.0f / 255) << samples << " samples per side";
    }
  }
}

TEST(Vectorize, RejectsBadInput) {
  test::expectParameterError([] { vectorizeVolume(Volume(), {}); }, "volume");
  test::expectParameterError([] { vectorizeVolume(Volume(8, 8, 8, 3), Volume(8, 8, 7, 1)); }, "mask");
  test::expectParameterError([] { vectorizeVolume(Volume(8, 8, 8, 3), Volume(8, 8, 8, 3)); }, "mask");
  VectorizeOptions options;
  options.spacing = 0;
  test::expectParameterError([&] { vectorizeVolume(Volume(8, 8, 8, 3), {}, options); }, "spacing");
  Volume nan(4, 4, 4, 1);
  nan.voxels[5] = std::nanf("");
  test::expectParameterError([&] { vectorizeVolume(nan, {}); }, "volume");
}

}  // namespace
}  // namespace texsynth
