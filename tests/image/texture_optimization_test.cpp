// Texture optimization: the discrete solver's energy never rises, results do not depend on
// the thread count, coordinates and colors agree, the least-squares solver blends, bad
// options are rejected.
#include "texsynth/image/texture_optimization.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "image_test_support.h"
#include "test_support.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/exemplar/analysis.h"

namespace texsynth {
namespace {

std::vector<ExemplarAnalysis> analysesFor(const Image& exemplar, const TextureOptimizationOptions& options) {
  std::vector<ExemplarAnalysis> analyses;
  for (const AnalysisOptions& analysisOptions : optimizationAnalysisOptions(options))
    analyses.push_back(analyzeExemplar(exemplar, analysisOptions));
  return analyses;
}

// A real exemplar when gimp-data is installed, else the synthetic pattern.
Image testExemplar() {
  if (auto path = gimpPattern("Stone/pink_marble.pat")) return test::loadPatternRgb(*path, 64);
  return test::makeTestPattern(64, 64);
}

struct Fixture {
  TextureOptimizationOptions options;
  Image exemplar = testExemplar();
  std::vector<ExemplarAnalysis> analyses;
  explicit Fixture(OptimizationSolver solver) {
    options.solver = solver;
    options.neighborhoodSizes = {9, 5};
    options.maxIterations = 4;
    analyses = analysesFor(exemplar, options);
  }
  TextureOptimizationResult run(int side = 64) const { return optimizeTexture(analyses, options, side, side); }
};

const Fixture& discreteFixture() {
  static const Fixture fixture(OptimizationSolver::Discrete);
  return fixture;
}

// Han et al.'s plain energy: no usage term, equal votes, k-coherence candidates only.
const Fixture& plainDiscreteFixture() {
  static const Fixture fixture = [] {
    Fixture plain(OptimizationSolver::Discrete);
    plain.options.coverageWeight = 0, plain.options.voteExponent = 0, plain.options.randomCandidates = 0;
    return plain;
  }();
  return fixture;
}

TEST(TextureOptimization, PlainDiscreteEnergyNeverRisesWithinAScale) {
  TextureOptimizationResult result = plainDiscreteFixture().run();
  ASSERT_FALSE(result.history.empty());
  int decreasingScales = 0;
  for (std::size_t i = 1; i < result.history.size(); ++i) {
    const OptimizationIteration& before = result.history[i - 1];
    const OptimizationIteration& after = result.history[i];
    if (after.iteration == 0) continue;  // a new level or neighborhood size starts over
    EXPECT_LE(after.energy, before.energy * (1 + 1e-6))
        << "level " << after.level << " N " << after.neighborhoodSize << " iteration " << after.iteration;
    if (after.energy < before.energy) ++decreasingScales;
  }
  EXPECT_GT(decreasingScales, 0) << "the iterations never lowered the energy";
  // The first E+M step of every scale lowers the energy clearly, not just by rounding.
  for (std::size_t i = 1; i < result.history.size(); ++i)
    if (result.history[i].iteration == 1 && result.history[i - 1].changedMatches > 0) {
      EXPECT_LT(result.history[i].energy, result.history[i - 1].energy);
    }
}

TEST(TextureOptimization, StopsWhenNoMatchChanges) {
  TextureOptimizationResult result = discreteFixture().run();
  for (std::size_t i = 0; i + 1 < result.history.size(); ++i)
    if (result.history[i].changedMatches == 0 && result.history[i].iteration > 0) {
      EXPECT_EQ(result.history[i + 1].iteration, 0) << "iterated on after the matches settled";
    }
}

TEST(TextureOptimization, DoesNotDependOnThreadCountAndDependsOnSeed) {
  const Fixture& fixture = discreteFixture();
  TextureOptimizationResult serial;
  {
    ThreadLimit limit(1);
    serial = fixture.run();
  }
  TextureOptimizationResult threaded = fixture.run();
  EXPECT_EQ(serial.coords.xy, threaded.coords.xy);
  EXPECT_EQ(serial.colors.pixels, threaded.colors.pixels);
  TextureOptimizationOptions other = fixture.options;
  other.seed = 7;
  EXPECT_NE(optimizeTexture(fixture.analyses, other, 64, 64).coords.xy, serial.coords.xy);
}

TEST(TextureOptimization, ColorsAreTheExemplarAtTheCoordinates) {
  const Fixture& fixture = discreteFixture();
  TextureOptimizationResult result = fixture.run(60);  // not a multiple of the stride: cropped
  ASSERT_EQ(result.coords.width, 60);
  ASSERT_EQ(result.colors.width, 60);
  EXPECT_EQ(result.colors.channels, 3);
  EXPECT_EQ(lookupColors(fixture.exemplar, result.coords).pixels, result.colors.pixels);
  for (std::size_t i = 0; i < result.coords.xy.size(); i += 2) {
    ASSERT_GE(result.coords.xy[i], 0);
    ASSERT_LT(result.coords.xy[i], fixture.exemplar.width);
  }
}

TEST(TextureOptimization, IsNotATilingOfTheExemplar) {
  const Fixture& fixture = discreteFixture();
  Image out = fixture.run(128).colors;
  const double synthesized = test::periodicityOf(out);
  const double tiled = test::periodicityOf(fixture.exemplar.tiled(128, 128));
  EXPECT_LT(synthesized, 0.3 * tiled) << "synthesized " << synthesized << " tiled " << tiled;
}

// A flat exemplar with sparse dark spots: the plain energy's cheapest optimum copies the flat
// part everywhere. Started from parallel synthesis, with the usage term and weighted votes, the
// output keeps the spots (their share of the pixels stays near the exemplar's).
TEST(TextureOptimization, KeepsSparseFeaturesOnAFlatBackground) {
  Image exemplar(64, 64, 3);
  for (float& value : exemplar.pixels) value = 0.6f;
  for (int spot = 0; spot < 14; ++spot) {
    const int cx = int(uniformBelow(hashKey(11, std::uint64_t(spot)), 58));
    const int cy = int(uniformBelow(hashKey(12, std::uint64_t(spot)), 58));
    for (int y = cy; y < cy + 5; ++y)
      for (int x = cx; x < cx + 5; ++x)
        for (int c = 0; c < 3; ++c) exemplar.at(x, y, c) = 0.1f + 0.03f * float((x + y) % 3);
  }
  auto darkShare = [](const Image& image) {
    int dark = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) dark += image.at(x, y, 0) < 0.35f;
    return double(dark) / (double(image.width) * image.height);
  };
  TextureOptimizationOptions options;
  options.neighborhoodSizes = {9, 5};
  const std::vector<ExemplarAnalysis> analyses = analysesFor(exemplar, options);
  const SourceCoordinates start = synthesizeParallelCoordinates(analyzeExemplar(exemplar), {.seed = 3}, 0, 0, 128, 128);
  const double kept = darkShare(optimizeTexture(analyses, options, 128, 128, noProgress(), &start).colors);
  EXPECT_GT(kept, 0.5 * darkShare(exemplar)) << "exemplar " << darkShare(exemplar) << " output " << kept;
  std::printf("dark share: exemplar %.3f, output %.3f\n", darkShare(exemplar), kept);
}

TEST(TextureOptimization, UsageTermAndWeightedVotesKeepTheExemplarComplete) {
  auto path = gimpPattern("Stone/rock.pat");
  TS_REQUIRE_DATA(path);
  const Image exemplar = test::loadPatternRgb(*path, 1024);
  TextureOptimizationOptions options;
  const std::vector<ExemplarAnalysis> analyses = analysesFor(exemplar, options);
  const SourceCoordinates start = synthesizeParallelCoordinates(analyzeExemplar(exemplar), {}, 0, 0, 160, 160);
  TextureOptimizationOptions plain = options;
  plain.coverageWeight = 0, plain.voteExponent = 0, plain.randomCandidates = 0;
  const MetricOptions metrics{.periodicitySamples = 100};
  const QualityMetrics full =
      evaluateImage(exemplar, optimizeTexture(analyses, options, 160, 160, noProgress(), &start).colors, metrics);
  const QualityMetrics without =
      evaluateImage(exemplar, optimizeTexture(analyses, plain, 160, 160, noProgress(), &start).colors, metrics);
  // Measured: completeness about 3 with, 20 without; sharpness about 1.0 with.
  EXPECT_LT(full.completeness, 0.6 * without.completeness)
      << "with " << full.completeness << " without " << without.completeness;
  EXPECT_GT(full.sharpness, 0.9);
  std::printf("rock completeness: with %.2f, without %.2f; coherence %.2f vs %.2f\n", full.completeness,
              without.completeness, full.coherence, without.coherence);
}

TEST(TextureOptimization, LeastSquaresBlendsAndHasNoCoordinates) {
  static const Fixture fixture(OptimizationSolver::LeastSquares);
  TextureOptimizationResult result = fixture.run();
  EXPECT_TRUE(result.coords.xy.empty());
  ASSERT_EQ(result.colors.width, 64);
  // Its energy falls over a level's iterations too (IRLS is not strictly monotone per step).
  const OptimizationIteration& first = result.history.front();
  double lowest = first.energy;
  for (const auto& step : result.history)
    if (step.level == first.level && step.neighborhoodSize == first.neighborhoodSize)
      lowest = std::min(lowest, step.energy);
  EXPECT_LT(lowest, first.energy);
  // Blending invents colors: some output pixel is no exemplar pixel.
  std::set<std::array<float, 3>> palette;
  for (int y = 0; y < fixture.exemplar.height; ++y)
    for (int x = 0; x < fixture.exemplar.width; ++x) {
      const float* c = fixture.exemplar.pixel(x, y);
      palette.insert({c[0], c[1], c[2]});
    }
  int invented = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const float* c = result.colors.pixel(x, y);
      invented += palette.count({c[0], c[1], c[2]}) == 0;
    }
  EXPECT_GT(invented, 64 * 64 / 4);
}

TEST(TextureOptimization, RejectsBadOptions) {
  const Fixture& fixture = discreteFixture();
  auto run = [&](TextureOptimizationOptions options, int w = 16, int h = 16) {
    optimizeTexture(fixture.analyses, options, w, h);
  };
  TextureOptimizationOptions o = fixture.options;
  test::expectParameterError([&] { run(o, 0, 16); }, "width");
  test::expectParameterError([&] { run(o, 16, -2); }, "height");
  o.levels = -1;
  test::expectParameterError([&] { run(o); }, "levels");
  o = fixture.options, o.neighborhoodSizes = {8};
  test::expectParameterError([&] { run(o); }, "neighborhood");
  o = fixture.options, o.neighborhoodSizes = {};
  test::expectParameterError([&] { run(o); }, "neighborhood");
  o = fixture.options, o.maxIterations = 0;
  test::expectParameterError([&] { run(o); }, "iterations");
  o = fixture.options, o.similarCount = 0;
  test::expectParameterError([&] { run(o); }, "similarCount");
  o = fixture.options, o.robustExponent = 3;
  test::expectParameterError([&] { run(o); }, "robustExponent");
  o = fixture.options, o.coverageWeight = -1;
  test::expectParameterError([&] { run(o); }, "coverageWeight");
  o = fixture.options, o.voteExponent = std::nanf("");
  test::expectParameterError([&] { run(o); }, "voteExponent");
  o = fixture.options, o.randomCandidates = -1;
  test::expectParameterError([&] { run(o); }, "randomCandidates");
  const SourceCoordinates small(0, 0, 8, 16);
  test::expectParameterError([&] { optimizeTexture(fixture.analyses, fixture.options, 16, 16, noProgress(), &small); },
                             "start");
  o = fixture.options, o.solver = OptimizationSolver::LeastSquares;  // wants one analysis per size, k = 1
  test::expectParameterError([&] { optimizeTexture(std::span(fixture.analyses).first(1), o, 16, 16); }, "analyses");
  test::expectParameterError([&] { parseOptimizationSolver("newton"); }, "solver");
  EXPECT_EQ(parseOptimizationSolver(optimizationSolverName(OptimizationSolver::LeastSquares)),
            OptimizationSolver::LeastSquares);
}

}  // namespace
}  // namespace texsynth
