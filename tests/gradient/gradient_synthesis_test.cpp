// Gradient solid synthesis (§4): determinism, bucket reuse, memory, fields, masks and bad options.
#include "texsynth/gradient/gradient_synthesis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>

#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"

namespace texsynth {
namespace {

// A 64x64 RGB exemplar of soft blobs on noise: structure at several scales.
Image blobs() {
  Image image(64, 64, 3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const float wave = 0.5f + 0.35f * std::sin(0.39f * x) * std::sin(0.29f * y);
      const float grain = 0.1f * uniform01(hashKey(7, latticeId(x, y)));
      image.at(x, y, 0) = wave + grain;
      image.at(x, y, 1) = 0.8f * wave;
      image.at(x, y, 2) = 1.0f - wave;
    }
  return image;
}

// Vertical stripes (period 16 along x), and the matching mask (the dark stripes).
Image stripes(bool mask = false) {
  Image image(64, 64, mask ? 1 : 3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < image.channels; ++c) {
        const bool dark = (x / 8) % 2 == 0;
        image.at(x, y, c) = mask ? (dark ? 1.0f : 0.0f) : (dark ? 0.15f : 0.85f);
      }
  return image;
}

GradientSynthesisOptions small(int n = 24) {
  GradientSynthesisOptions options;
  options.voxels = Vec3i::Constant(n);
  options.iterations = 1;
  return options;
}

// Two small levels (N = 5 at spacing 2, 9 at 1): every step of the synthesis, at a test's cost.
GradientExemplarOptions fast() {
  GradientExemplarOptions options;
  options.levelSizes = {5, 9};
  return options;
}

const GradientExemplars& blobExemplars() {
  static const GradientExemplars exemplars({blobs()}, {}, fast());
  return exemplars;
}

TEST(GradientSynthesis, SameSeedSameBitsForAnyThreadCount) {
  const GradientSolid all = synthesizeGradientSolid({&blobExemplars()}, small());
  GradientSolid one;
  {
    ThreadLimit limit(1);
    one = synthesizeGradientSolid({&blobExemplars()}, small());
  }
  EXPECT_EQ(all.positive, one.positive);
  GradientSynthesisOptions other = small();
  other.seed = 2;
  EXPECT_NE(synthesizeGradientSolid({&blobExemplars()}, other).positive, all.positive);
}

TEST(GradientSynthesis, BucketReuseGivesTheResultOfFullBuckets) {
  GradientSynthesisOptions reuse = small(56), full = small(56);
  full.bucketReuse = false;
  GradientSynthesisReport reuseReport, fullReport;
  const GradientSolid a = synthesizeGradientSolid({&blobExemplars()}, reuse, &reuseReport);
  const GradientSolid b = synthesizeGradientSolid({&blobExemplars()}, full, &fullReport);
  EXPECT_EQ(a.positive, b.positive);
  EXPECT_LT(reuseReport.peakBucketBytes, fullReport.peakBucketBytes);
}

// Sanitizer builds run at -O0, where 256^3 takes minutes: the release suite measures it.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

TEST(GradientSynthesis, BucketWindowOf256CubedStaysFarBelowAVoxelArray) {
  if (kSanitized) GTEST_SKIP() << "256^3 at -O0 with sanitizers takes minutes; the release suite runs it";
  // Only the memory is of interest: one level of small slices, one iteration, one check point per cube.
  GradientExemplarOptions oneLevel;
  oneLevel.levelSizes = {5};
  const GradientExemplars exemplars({blobs()}, {}, oneLevel);
  GradientSynthesisOptions options = small(256);
  options.checkPoints = 1;
  GradientSynthesisReport report;
  const GradientSolid solid = synthesizeGradientSolid({&exemplars}, options, &report);
  const double rgbVoxels = 256.0 * 256 * 256 * 3 * sizeof(float);  // the raster, as floats
  EXPECT_LT(double(report.peakBucketBytes), 0.5 * rgbVoxels);
  EXPECT_LT(report.peakBucketBytes, report.fullBucketBytes / 4);
  EXPECT_EQ(solid.controls, Vec3i::Constant(65));
}

TEST(GradientSynthesis, KeepsTheExemplarsColours) {
  const GradientSolid solid = synthesizeGradientSolid({&blobExemplars()}, small(32));
  ASSERT_EQ(solid.channels, 3);
  double mean = 0;
  for (std::int64_t c = 0; c < solid.controlCount(); ++c) mean += solid.positive[std::size_t(c) * 12];
  mean /= double(solid.controlCount());
  EXPECT_GT(mean, 0.35);
  EXPECT_LT(mean, 0.75);
}

TEST(GradientSynthesis, MaskedSynthesisSeparatesTheRegions) {
  const GradientExemplars exemplars({stripes()}, {stripes(true)}, fast());
  GradientSynthesisOptions options = small(32);
  GradientSynthesisReport report;
  const GradientSolid solid = synthesizeGradientSolid({&exemplars}, options, &report);
  ASSERT_TRUE(solid.hasRegions());
  EXPECT_GT(report.boundaryControls, 0);
  // Evaluation never blends across the boundary: every voxel is near one of the two stripe colours.
  GradientEvaluateOptions exact;
  int mixed = 0, total = 0;
  for (int z = 1; z < 31; z += 3)
    for (int y = 1; y < 31; y += 3)
      for (int x = 1; x < 31; ++x) {
        float rgb[3];
        evaluateGradientSolid(solid, Vec3f(float(x), float(y), float(z)), exact, rgb);
        const bool inside = evaluateGradientDistance(solid, Vec3f(float(x), float(y), float(z))) >= 0;
        // Positive: the mask's (dark) side.
        mixed += inside ? rgb[0] > 0.5f : rgb[0] < 0.5f;
        ++total;
      }
  EXPECT_LT(mixed, total / 20);
}

// A solid of layers normal to x (as the lazy solid's test): I_xy varies along its u (= x), I_zx along its v (= x),
// I_yz is flat. Returns the mean absolute colour step along world x and along world y. Independent searches: the
// flat I_yz is no slice of that solid (its slices are flat but not all mid-gray), so crossbars would pin E_y to
// the stripes' mid-gray phase.
std::pair<double, double> stripeSteps(const std::function<Quatf(const Vec3f&)>& orientation) {
  const int size = 32;
  Image xy(size, size, 3), yz(size, size, 3, 0.5f), zx(size, size, 3);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      for (int c = 0; c < 3; ++c) {
        xy.at(i, j, c) = 0.5f + 0.4f * std::sin(6.2831853f * float(i) / 16.0f);
        zx.at(i, j, c) = 0.5f + 0.4f * std::sin(6.2831853f * float(j) / 16.0f);
      }
  const GradientExemplars exemplars({xy, yz, zx}, {}, fast());
  GradientSynthesisOptions options = small(32);
  options.iterations = 3;
  options.crossbar = false;
  options.orientation = orientation;
  const GradientSolid solid = synthesizeGradientSolid({&exemplars}, options);
  double stepX = 0, stepY = 0;
  float a[3], b[3], c[3];
  const GradientEvaluateOptions exact;
  for (int z = 2; z < 30; z += 2)
    for (int y = 2; y < 29; ++y)
      for (int x = 2; x < 29; ++x) {
        evaluateGradientSolid(solid, Vec3f(float(x), float(y), float(z)), exact, a);
        evaluateGradientSolid(solid, Vec3f(float(x + 1), float(y), float(z)), exact, b);
        evaluateGradientSolid(solid, Vec3f(float(x), float(y + 1), float(z)), exact, c);
        stepX += std::abs(a[0] - b[0]);
        stepY += std::abs(a[0] - c[0]);
      }
  return {stepX, stepY};
}

TEST(GradientSynthesis, StripesFollowARotatedField) {
  const auto [identityX, identityY] = stripeSteps({});
  EXPECT_GT(identityX, 2.0 * identityY) << identityX << " vs " << identityY;
  const Quatf quarter(Eigen::AngleAxisf(1.5707963f, Vec3f::UnitZ()));
  const auto [rotatedX, rotatedY] = stripeSteps([quarter](const Vec3f&) { return quarter; });
  EXPECT_GT(rotatedY, 2.0 * rotatedX) << rotatedX << " vs " << rotatedY;
}

TEST(GradientSynthesis, RejectsBadOptions) {
  auto bad = [](auto change) {
    GradientSynthesisOptions options = small();
    change(options);
    return options;
  };
  EXPECT_THROW(synthesizeGradientSolid({}, small()), ParameterError);
  EXPECT_THROW(synthesizeGradientSolid({&blobExemplars()}, bad([](auto& o) { o.voxels.x() = 1; })), ParameterError);
  EXPECT_THROW(synthesizeGradientSolid({&blobExemplars()}, bad([](auto& o) { o.spacing = 3; })), ParameterError);
  EXPECT_THROW(synthesizeGradientSolid({&blobExemplars()}, bad([](auto& o) { o.matchedSlices = 1; })), ParameterError);
  EXPECT_THROW(synthesizeGradientSolid({&blobExemplars()}, bad([](auto& o) { o.checkPoints = 0; })), ParameterError);
  EXPECT_THROW(GradientExemplars({Image(8, 8, 3)}, {}), ParameterError);  // too small for three levels
  EXPECT_THROW(GradientExemplars({blobs(), blobs()}, {}), ParameterError);
}

}  // namespace
}  // namespace texsynth
