// Texture optimization: the discrete solver's energy never rises, results do not depend on
// the thread count, coordinates and colors agree, the least-squares solver blends, bad
// options are rejected.
#include "texsynth/image/texture_optimization.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <set>

#include "image_test_support.h"
#include "test_support.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/image/flat_patch_share.h"
#include "texsynth/image/optimization_grid.h"
#include "texsynth/image/seam_blend.h"

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
    options.maxIterations = options.finestIterations = 4;
    analyses = analysesFor(exemplar, options);
  }
  TextureOptimizationResult run(int side = 64) const { return optimizeTexture(analyses, options, side, side); }
};

const Fixture& discreteFixture() {
  static const Fixture fixture(OptimizationSolver::Discrete);
  return fixture;
}

// Han et al.'s plain energy: no usage term, equal votes, k-coherence candidates only, on a
// fixed lattice of active neighborhoods (a moved one measures other neighborhoods).
const Fixture& plainDiscreteFixture() {
  static const Fixture fixture = [] {
    Fixture plain(OptimizationSolver::Discrete);
    plain.options.coverageWeight = 0, plain.options.voteExponent = 0, plain.options.randomCandidates = 0;
    plain.options.movingLattice = false;
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
  // Feathered at the seams (seam_blend_test.cpp), crisp without.
  EXPECT_EQ(seamBlendedColors(fixture.exemplar, result.coords, 3, fixture.options.seamBlend).pixels,
            result.colors.pixels);
  TextureOptimizationOptions crisp = fixture.options;
  crisp.seamBlend = 0;
  const TextureOptimizationResult cut = optimizeTexture(fixture.analyses, crisp, 60, 60);
  EXPECT_EQ(cut.coords.xy, result.coords.xy);
  EXPECT_EQ(lookupColors(fixture.exemplar, cut.coords).pixels, cut.colors.pixels);
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

// A GIMP pattern cropped to at most `side` pixels, the solver's analyses for the default options
// and a parallel start of an `output`-pixel square: what the real-data tests share. Empty
// without gimp-data.
struct RealCase {
  Image exemplar;
  std::vector<ExemplarAnalysis> analyses;
  SourceCoordinates start;
};
std::optional<RealCase> realCase(const char* pattern, int side, int output) {
  auto path = gimpPattern(pattern);
  if (!path) return std::nullopt;
  RealCase real{test::loadPatternRgb(*path, side), {}, {}};
  real.analyses = analysesFor(real.exemplar, TextureOptimizationOptions{});
  // Without the continuation bias, as parallelOptimizationStart makes optimize's own start.
  real.start =
      synthesizeParallelCoordinates(analyzeExemplar(real.exemplar), {.continuationBias = 0}, 0, 0, output, output);
  return real;
}

TEST(TextureOptimization, UsageTermAndWeightedVotesKeepTheExemplarComplete) {
  const std::optional<RealCase> real = realCase("Stone/rock.pat", 1024, 160);
  TS_REQUIRE_DATA(real);
  const auto& [exemplar, analyses, start] = *real;
  TextureOptimizationOptions options;
  TextureOptimizationOptions plain = options;
  plain.coverageWeight = 0, plain.voteExponent = 0, plain.randomCandidates = 0;
  const MetricOptions metrics{.periodicitySamples = 100};
  const QualityMetrics full =
      evaluateImage(exemplar, optimizeTexture(analyses, options, 160, 160, noProgress(), &start).colors, metrics);
  const QualityMetrics without =
      evaluateImage(exemplar, optimizeTexture(analyses, plain, 160, 160, noProgress(), &start).colors, metrics);
  // Measured: completeness about 6 with, 14 without; sharpness about 1.0 with.
  EXPECT_LT(full.completeness, 0.6 * without.completeness)
      << "with " << full.completeness << " without " << without.completeness;
  EXPECT_GT(full.sharpness, 0.9);
  std::printf("rock completeness: with %.2f, without %.2f; coherence %.2f vs %.2f\n", full.completeness,
              without.completeness, full.coherence, without.coherence);
}

// Moving the lattice of active neighborhoods carries every match along: on an output that is a
// coherent copy of the exemplar, the moved neighborhoods still match exactly where their moved
// match is an allowed centre, and the offsets stay inside the stride.
TEST(TextureOptimization, MovingTheLatticeCarriesMatchesAlong) {
  const Fixture& fixture = discreteFixture();
  const ExemplarAnalysis& analysis = fixture.analyses.back();
  const int level = analysis.levelCount() - 1, side = 64;
  detail::OptimizationGrid grid(analysis, level, side, side, 9, detail::PixelNorm::Euclidean);
  ASSERT_EQ(grid.stride, 2);
  std::vector<std::int32_t> copy(std::size_t(side) * side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) copy[std::size_t(y) * side + x] = analysis.pixelIndex(x, y);
  std::vector<float> query(std::size_t(grid.window.dimension()));
  std::vector<int> columns(std::size_t(grid.window.size));
  auto colorOf = [&](std::int64_t sample) { return grid.window.exemplarColor(copy[std::size_t(sample)]); };
  for (std::uint64_t key = 1; key <= 6; ++key) {
    grid.offsetX = grid.offsetY = 0;
    detail::Matches matches(grid.activeCount());
    for (std::int64_t a = 0; a < grid.activeCount(); ++a)  // each neighborhood's own source
      matches.pixel[std::size_t(a)] =
          copy[std::size_t((a / grid.activeWidth()) * grid.stride * side + (a % grid.activeWidth()) * grid.stride)];
    grid.moveLattice(key, matches);
    ASSERT_TRUE(grid.offsetX >= 0 && grid.offsetX < grid.stride && grid.offsetY >= 0 && grid.offsetY < grid.stride);
    int exact = 0, inside = 0;
    for (std::int64_t a = 0; a < grid.activeCount(); ++a) {
      const int x = int(a % grid.activeWidth()) * grid.stride + grid.offsetX;
      const int y = int(a / grid.activeWidth()) * grid.stride + grid.offsetY;
      const std::int32_t own = copy[std::size_t(y % side) * side + std::size_t(x % side)];
      if (!grid.window.isAllowedCentre(own) || !grid.window.isAllowedCentre(matches.pixel[std::size_t(a)])) continue;
      ++inside;
      grid.gather(a, colorOf, query.data());
      exact += matches.pixel[std::size_t(a)] == own &&
               grid.window.distance(query.data(), own, 1e30f, columns.data()) == 0.0f;
    }
    EXPECT_GT(inside, grid.activeCount() / 2);
    EXPECT_EQ(exact, inside) << "key " << key;
  }
}

// GIMP cracked, thin dark cracks and fine relief on a flat gray: every E+M level flattens it
// (flat share 0.14 -> 0.73 at the coarsest), and without the guard most of the output ends up
// one gray. With it, the output is never flatter than the start it was given, plus the guard's
// tolerance.
TEST(TextureOptimization, CollapseGuardKeepsAFlatBackgroundsFeatures) {
  const std::optional<RealCase> real = realCase("Stone/cracked.pat", 128, 96);
  TS_REQUIRE_DATA(real);
  const auto& [exemplar, analyses, start] = *real;
  const detail::FlatPatchShare flatness(analyses.back().levels.back(), analyses.back().colorChannels);
  const TextureOptimizationOptions guarded;
  TextureOptimizationOptions unguarded;
  unguarded.collapseTolerance = 1;
  auto flatShare = [&](const SourceCoordinates& coords) {
    return flatness.of(coords.pixelIndices(exemplar.width), coords.width, coords.height);
  };
  const TextureOptimizationResult withGuard = optimizeTexture(analyses, guarded, 96, 96, noProgress(), &start);
  const TextureOptimizationResult without = optimizeTexture(analyses, unguarded, 96, 96, noProgress(), &start);
  const double startShare = flatShare(start);
  EXPECT_GT(flatShare(without.coords), startShare + 0.15) << "the collapse this guards against did not happen";
  EXPECT_EQ(without.undoneLevels, 0);
  EXPECT_LE(flatShare(withGuard.coords), startShare + guarded.collapseTolerance);
  EXPECT_GT(withGuard.undoneLevels, 0);
  std::printf("cracked flat share: start %.2f, guarded %.2f (%d levels undone), unguarded %.2f\n", startShare,
              flatShare(withGuard.coords), withGuard.undoneLevels, flatShare(without.coords));
}

// The same exemplar with the feature channel as fallback: the level colors alone flatten is run
// again on the analyses with it, and the cracks stay (sharpness about 0.7 without, 0.9 with, as
// GIMP cracked at 256^2).
TEST(TextureOptimization, FeatureChannelKeepsAFlatBackgroundsCracks) {
  const std::optional<RealCase> real = realCase("Stone/cracked.pat", 128, 96);
  TS_REQUIRE_DATA(real);
  const auto& [exemplar, analyses, start] = *real;
  const TextureOptimizationOptions options;
  int calls = 0;
  auto featureAnalyses = [&] {
    ++calls;
    std::vector<ExemplarAnalysis> made;
    for (const AnalysisOptions& analysisOptions :
         withFeatureChannel(optimizationAnalysisOptions(options), exemplar, kOptimizationFeatureWeight))
      made.push_back(analyzeExemplar(exemplar, analysisOptions));
    return made;
  };
  const TextureOptimizationResult colorsOnly = optimizeTexture(analyses, options, 96, 96, noProgress(), &start);
  const TextureOptimizationResult featured =
      optimizeTexture(analyses, options, 96, 96, noProgress(), &start, featureAnalyses);
  EXPECT_EQ(calls, 1);
  EXPECT_GT(featured.featureLevels, 0);
  EXPECT_LT(featured.undoneLevels, colorsOnly.undoneLevels);
  const detail::FlatPatchShare flatness(analyses.back().levels.back(), analyses.back().colorChannels);
  auto flatShare = [&](const SourceCoordinates& coords) {
    return flatness.of(coords.pixelIndices(exemplar.width), coords.width, coords.height);
  };
  EXPECT_LE(flatShare(featured.coords), flatShare(start) + options.collapseTolerance);
  const MetricOptions metrics{.periodicitySamples = 100};
  const double with = evaluateImage(exemplar, featured.colors, metrics).sharpness;
  const double without = evaluateImage(exemplar, colorsOnly.colors, metrics).sharpness;
  EXPECT_GT(with, without + 0.1) << "with " << with << " without " << without;
  std::printf("cracked sharpness: colors only %.2f (%d levels undone), feature channel %.2f (%d levels)\n", without,
              colorsOnly.undoneLevels, with, featured.featureLevels);
}

// An exemplar whose levels the guard keeps never asks for the feature channel: the same bits.
TEST(TextureOptimization, FeatureChannelIsOnlyMadeWhenALevelCollapses) {
  const Fixture& fixture = discreteFixture();
  int calls = 0;
  auto featureAnalyses = [&] {
    ++calls;
    return std::vector<ExemplarAnalysis>{};
  };
  const TextureOptimizationResult result =
      optimizeTexture(fixture.analyses, fixture.options, 64, 64, noProgress(), nullptr, featureAnalyses);
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(result.featureLevels, 0);
  EXPECT_EQ(result.coords.xy, fixture.run().coords.xy);
}

TEST(TextureOptimization, WithFeatureChannelMarksDistinctiveColorsOnly) {
  TextureOptimizationOptions options;
  const std::vector<AnalysisOptions> plain = optimizationAnalysisOptions(options);
  Image flat(32, 32, 3);
  for (float& value : flat.pixels) value = 0.5f;
  EXPECT_TRUE(withFeatureChannel(plain, flat, 0.5f).front().featureMask.empty());  // no distinctive colors
  const Image pattern = test::makeTestPattern(32, 32);
  EXPECT_TRUE(withFeatureChannel(plain, pattern, 0.0f).front().featureMask.empty());
  const std::vector<AnalysisOptions> featured = withFeatureChannel(plain, pattern, 0.5f);
  ASSERT_EQ(featured.size(), plain.size());
  for (const AnalysisOptions& analysis : featured) {
    EXPECT_EQ(analysis.featureMask.width, 32);
    EXPECT_EQ(analysis.featureWeight, 0.5f);
  }
  test::expectParameterError([&] { withFeatureChannel(plain, pattern, -1.0f); }, "feature weight");
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
  o = fixture.options, o.finestIterations = 0;
  test::expectParameterError([&] { run(o); }, "finestIterations");
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
  o = fixture.options, o.seamBlend = 5;
  test::expectParameterError([&] { run(o); }, "seamBlend");
  o = fixture.options, o.collapseTolerance = std::nan("");
  test::expectParameterError([&] { run(o); }, "collapseTolerance");
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
