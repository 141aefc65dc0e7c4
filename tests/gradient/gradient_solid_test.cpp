// The representation: corner reproduction, polynomial exactness, C1 continuity, the weight table,
// regions, and the SolidTexture adapter.
#include "texsynth/gradient/gradient_solid.h"

#include <gtest/gtest.h>

#include <cmath>

#include "texsynth/core/random.h"
#include "texsynth/gradient/gradient_solid_texture.h"
#include "texsynth/gradient/tricubic_basis.h"

namespace texsynth {
namespace {

// A solid with random values in [0,1] and gradients up to `slope` per cube edge.
GradientSolid randomSolid(const Vec3i& voxels, int channels, float slope, std::uint64_t seed) {
  GradientSolid solid = GradientSolid::zeros(voxels, channels);
  for (std::size_t n = 0; n < solid.positive.size(); ++n) {
    const bool value = (n / std::size_t(channels)) % 4 == 0;
    const float u = uniform01(hashKey(seed, n));
    solid.positive[n] = value ? u : slope * (2 * u - 1);
  }
  return solid;
}

float evaluateChannel(const GradientSolid& solid, const Vec3f& p, int channel = 0,
                      const GradientEvaluateOptions& options = {}) {
  float out[4];
  evaluateGradientSolid(solid, p, options, out);
  return out[channel];
}

TEST(GradientSolid, ControlCountsCoverTheRaster) {
  EXPECT_EQ(GradientSolid::controlsFor(128, 4), 33);
  EXPECT_EQ(GradientSolid::controlsFor(129, 4), 33);
  EXPECT_EQ(GradientSolid::controlsFor(130, 4), 34);
  EXPECT_EQ(GradientSolid::controlsFor(1, 4), 2);
  for (int n = 1; n < 40; ++n)
    for (int d = 1; d < 9; ++d) {
      const int controls = GradientSolid::controlsFor(n, d);
      EXPECT_GE((controls - 1) * d, n - 1);
      EXPECT_LT((controls - 2) * d, std::max(n - 1, 1));
    }
}

TEST(GradientSolid, ReproducesCornerValuesAndGradients) {
  const GradientSolid solid = randomSolid({17, 13, 21}, 3, 0.8f, 7);
  const float h = 4e-3f;
  for (int k = 1; k < solid.controls.z() - 1; k += 2)
    for (int j = 1; j < solid.controls.y() - 1; j += 2)
      for (int i = 1; i < solid.controls.x() - 1; ++i) {
        const Vec3f p = Vec3f(float(i), float(j), float(k)) * float(solid.spacing);
        const float* set = &solid.positive[std::size_t(solid.controlIndex(i, j, k)) * solid.setSize()];
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(evaluateChannel(solid, p, c), set[c], 1e-6f);
          for (int a = 0; a < 3; ++a) {  // one-sided, second order (the solid is C1, not C2, at p)
            const Vec3f step = Vec3f::Unit(a) * h;
            const float derivative = (-3 * evaluateChannel(solid, p, c) + 4 * evaluateChannel(solid, p + step, c) -
                                      evaluateChannel(solid, p + 2 * step, c)) /
                                     (2 * h) * solid.spacing;
            EXPECT_NEAR(derivative, set[(1 + a) * 3 + c], 2e-3f);
          }
        }
      }
}

// f = a sum of one cubic per axis: its mixed derivatives vanish, so the interpolant is exact.
TEST(GradientSolid, ExactOnSeparableCubics) {
  auto cubic = [](float t, float a, float b, float c, float d) { return a + t * (b + t * (c + t * d)); };
  auto slope = [](float t, float b, float c, float d) { return b + t * (2 * c + 3 * t * d); };
  const float px[4] = {0.1f, 0.02f, -1e-3f, 2e-5f}, py[4] = {-0.2f, 0.01f, 5e-4f, -1e-5f},
              pz[4] = {0.3f, -0.03f, 1e-3f, 1e-5f};
  auto f = [&](const Vec3f& p) {
    return cubic(p.x(), px[0], px[1], px[2], px[3]) + cubic(p.y(), py[0], py[1], py[2], py[3]) +
           cubic(p.z(), pz[0], pz[1], pz[2], pz[3]);
  };
  GradientSolid solid = GradientSolid::zeros({33, 29, 25}, 1);
  for (int k = 0; k < solid.controls.z(); ++k)
    for (int j = 0; j < solid.controls.y(); ++j)
      for (int i = 0; i < solid.controls.x(); ++i) {
        const Vec3f p = Vec3f(float(i), float(j), float(k)) * float(solid.spacing);
        float* set = &solid.positive[std::size_t(solid.controlIndex(i, j, k)) * 4];
        set[0] = f(p);
        set[1] = slope(p.x(), px[1], px[2], px[3]) * solid.spacing;
        set[2] = slope(p.y(), py[1], py[2], py[3]) * solid.spacing;
        set[3] = slope(p.z(), pz[1], pz[2], pz[3]) * solid.spacing;
      }
  for (int n = 0; n < 2000; ++n) {
    const Vec3f p(uniform01(hashKey(1, n)) * 32, uniform01(hashKey(2, n)) * 28, uniform01(hashKey(3, n)) * 24);
    EXPECT_NEAR(evaluateChannel(solid, p), f(p), 2e-4f * (1 + std::abs(f(p))));
  }
}

TEST(GradientSolid, IsC1AcrossCubeFaces) {
  const GradientSolid solid = randomSolid({25, 25, 25}, 1, 1.0f, 3);
  const float e = 1e-3f, h = 1e-3f;
  for (int n = 0; n < 500; ++n) {
    const int axis = n % 3;
    Vec3f p(uniform01(hashKey(4, n)) * 24, uniform01(hashKey(5, n)) * 24, uniform01(hashKey(6, n)) * 24);
    p[axis] = float(solid.spacing * (1 + n % 5));  // on a face
    const Vec3f step = Vec3f::Unit(axis);
    const float left = evaluateChannel(solid, p - e * step), right = evaluateChannel(solid, p + e * step);
    EXPECT_NEAR(left, right, 5e-3f);
    const float leftSlope = (evaluateChannel(solid, p - e * step) - evaluateChannel(solid, p - (e + h) * step)) / h;
    const float rightSlope = (evaluateChannel(solid, p + (e + h) * step) - evaluateChannel(solid, p + e * step)) / h;
    EXPECT_NEAR(leftSlope, rightSlope, 0.02f);
  }
}

TEST(GradientSolid, TableEntriesAreTheExactWeights) {
  const TricubicWeightTable table(17);
  float exact[32];
  tricubicWeights(3.0f / 16, 10.0f / 16, 16.0f / 16, exact);
  for (int w = 0; w < 32; ++w) EXPECT_FLOAT_EQ(table.entry(3, 10, 16)[w], exact[w]);
  float sum = 0;
  for (int p = 0; p < 8; ++p) sum += exact[4 * p];  // the value weights form a partition of unity
  EXPECT_NEAR(sum, 1.0f, 1e-6f);
}

TEST(GradientSolid, TableLookupsEqualTrilinearFetchesOfTheEntries) {
  for (int samples : {33, 17}) {
    const TricubicWeightTable table(samples);
    for (int n = 0; n < 1000; ++n) {
      const float u = uniform01(hashKey(1, n)), v = uniform01(hashKey(2, n)), w = uniform01(hashKey(3, n));
      float factored[32], fetched[32];
      table.weights(u, v, w, factored);
      table.weightsFromEntries(u, v, w, fetched);
      for (int k = 0; k < 32; ++k) EXPECT_NEAR(factored[k], fetched[k], 1e-6f);
    }
  }
}

TEST(GradientSolid, FirstOrderApproximationIsTheNearestTaylorExpansion) {
  const GradientSolid solid = randomSolid({17, 17, 17}, 1, 0.5f, 5);
  GradientEvaluateOptions firstOrder;
  firstOrder.exact = false;
  const Vec3f p(8.7f, 3.2f, 12.1f);  // nearest control (2, 1, 3)
  const float* set = &solid.positive[std::size_t(solid.controlIndex(2, 1, 3)) * 4];
  const float expected = set[0] + set[1] * (8.7f / 4 - 2) + set[2] * (3.2f / 4 - 1) + set[3] * (12.1f / 4 - 3);
  EXPECT_NEAR(evaluateChannel(solid, p, 0, firstOrder), expected, 1e-6f);
}

// Two regions split by the plane x = 10.3: red on the positive side, blue on the negative.
GradientSolid planeSolid() {
  GradientSolid solid = GradientSolid::zeros({33, 17, 17}, 3);
  const std::size_t n = std::size_t(solid.controlCount());
  solid.distance.assign(4 * n, 0.0f);
  solid.negativeIndex.assign(n, -1);
  for (int k = 0; k < solid.controls.z(); ++k)
    for (int j = 0; j < solid.controls.y(); ++j)
      for (int i = 0; i < solid.controls.x(); ++i) {
        const std::size_t c = std::size_t(solid.controlIndex(i, j, k));
        solid.distance[4 * c] = float(i * solid.spacing) - 10.3f;
        solid.distance[4 * c + 1] = float(solid.spacing);
        solid.positive[c * 12 + 0] = 1;  // red
        if (i == 2 || i == 3) {
          solid.negativeIndex[c] = std::int32_t(solid.negative.size() / 12);
          solid.negative.resize(solid.negative.size() + 12, 0.0f);
          solid.negative[solid.negative.size() - 12 + 2] = 1;  // blue
        } else if (i < 2) {
          solid.positive[c * 12 + 0] = 0, solid.positive[c * 12 + 2] = 1;
        }
      }
  solid.checkConsistent();
  return solid;
}

TEST(GradientSolid, RegionBoundaryFollowsTheZeroLevelSet) {
  const GradientSolid solid = planeSolid();
  GradientEvaluateOptions sharp;
  sharp.antialiasVoxels = 1e-3f;
  for (float x : {9.0f, 10.0f, 10.29f, 10.31f, 10.6f, 11.5f}) {
    float rgb[3];
    evaluateGradientSolid(solid, Vec3f(x, 7.3f, 5.1f), sharp, rgb);
    EXPECT_NEAR(evaluateGradientDistance(solid, Vec3f(x, 7.3f, 5.1f)), x - 10.3f, 1e-4f);
    if (x < 10.3f)
      EXPECT_TRUE(rgb[2] > 0.99f && rgb[0] < 0.01f) << x;
    else
      EXPECT_TRUE(rgb[0] > 0.99f && rgb[2] < 0.01f) << x;
  }
  GradientEvaluateOptions antialiased;  // half way on the level set
  antialiased.antialiasVoxels = 1.0f;
  float blended[3];
  evaluateGradientSolid(solid, Vec3f(10.3f, 7.3f, 5.1f), antialiased, blended);
  EXPECT_NEAR(blended[0], 0.5f, 1e-3f);
  EXPECT_NEAR(blended[2], 0.5f, 1e-3f);
}

TEST(GradientSolid, DetailIsDeterministicGrainOfTheFittedSigma) {
  GradientSolid solid = randomSolid({17, 17, 17}, 1, 0.0f, 2);
  solid.detail.assign(solid.positive.size(), 0.0f);
  for (std::size_t n = 0; n < solid.detail.size(); n += 4) solid.detail[n] = 0.05f;  // sigma 0.05, flat
  GradientEvaluateOptions detail;
  detail.detail = true;
  double sum = 0, squares = 0;
  int count = 0;
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const Vec3f p = Vec3f(float(x), float(y), float(z));
        const float grain = evaluateChannel(solid, p, 0, detail) - evaluateChannel(solid, p);
        const Vec3f q = p + Vec3f::Constant(0.2f);  // the same voxel: the same grain
        EXPECT_NEAR(grain, evaluateChannel(solid, q, 0, detail) - evaluateChannel(solid, q), 1e-6f);
        sum += grain, squares += double(grain) * grain, ++count;
      }
  const double mean = sum / count, deviation = std::sqrt(squares / count - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.01);
  EXPECT_NEAR(deviation, 0.05, 0.005);
}

TEST(GradientSolidTexture, SpansTheBoxAndAnswersLikeTheSolid) {
  auto solid = std::make_shared<GradientSolid>(randomSolid({32, 16, 16}, 3, 0.3f, 9));
  Box3f box;
  box.extend(Vec3f(-1, -1, -1));
  box.extend(Vec3f(1, 0, 0));
  GradientSolidTextureOptions options;
  options.placement = gradientSolidPlacement(*solid, box);
  options.detail = false;
  const auto texture = makeGradientSolidTexture(solid, options);
  EXPECT_EQ(texture->channels(), 3);
  // The box's x runs over the 32 voxels: world -1 + (x + 0.5) / 16 is voxel x's centre.
  const std::vector<Vec3f> points = {Vec3f(-1 + 5.5f / 16, -1 + 3.5f / 16, -1 + 7.5f / 16)};
  std::vector<float> values(3);
  texture->evaluate(points, {}, values);
  float direct[3];
  evaluateGradientSolid(*solid, Vec3f(5, 3, 7), {}, direct);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(values[std::size_t(c)], direct[c], 1e-5f);
}

}  // namespace
}  // namespace texsynth
