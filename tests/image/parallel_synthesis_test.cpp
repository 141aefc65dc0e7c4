#include "texsynth/image/parallel_synthesis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/eval/metrics.h"

namespace texsynth {
namespace {

// One analysis of a 32x32 synthetic pattern, shared by the tests (analysis is the slow part).
const ExemplarAnalysis& patternAnalysis() {
  static const ExemplarAnalysis analysis = analyzeExemplar(test::makeTestPattern(32, 32));
  return analysis;
}

SourceCoordinates cropCoordinates(const SourceCoordinates& coords, int x0, int y0, int w, int h) {
  SourceCoordinates out(x0, y0, w, h);
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) {
      out.at(x, y)[0] = coords.at(x, y)[0];
      out.at(x, y)[1] = coords.at(x, y)[1];
    }
  return out;
}

TEST(ParallelSynthesis, WindowIsBitIdenticalToTheSameRegionOfALargerOutput) {
  const ExemplarAnalysis& analysis = patternAnalysis();
  ParallelSynthesisOptions options{.seed = 5};
  SourceCoordinates large = synthesizeParallelCoordinates(analysis, options, -37, -21, 100, 80);
  SourceCoordinates window = synthesizeParallelCoordinates(analysis, options, 13, 7, 29, 23);
  EXPECT_EQ(window.xy, cropCoordinates(large, 13, 7, 29, 23).xy);
  // An odd, negative origin exercises floor division at every level.
  SourceCoordinates negative = synthesizeParallelCoordinates(analysis, options, -35, -19, 17, 9);
  EXPECT_EQ(negative.xy, cropCoordinates(large, -35, -19, 17, 9).xy);
  Image colors = synthesizeParallel(analysis, options, 13, 7, 29, 23);
  EXPECT_EQ(colors.pixels, lookupColors(analysis.levels.back().image, window).pixels);
}

TEST(ParallelSynthesis, WindowsAgreeForEverySubpassGridAndPerLevelNeighborhoods) {
  AnalysisOptions perLevel;
  perLevel.levelNeighborhoodSizes = {3, 5, 7};
  static const ExemplarAnalysis mixed = analyzeExemplar(test::makeTestPattern(32, 32), perLevel);
  for (int s : {1, 2, 3}) {
    SCOPED_TRACE("s = " + std::to_string(s));
    ParallelSynthesisOptions options{.seed = 3, .subpassGrid = s};
    SourceCoordinates large = synthesizeParallelCoordinates(mixed, options, -20, -9, 90, 70);
    SourceCoordinates window = synthesizeParallelCoordinates(mixed, options, 11, 5, 23, 19);
    EXPECT_EQ(window.xy, cropCoordinates(large, 11, 5, 23, 19).xy);
    SourceCoordinates serial;
    {
      ThreadLimit limit(1);
      serial = synthesizeParallelCoordinates(mixed, options, 11, 5, 23, 19);
    }
    EXPECT_EQ(serial.xy, window.xy);
  }
  // More subpasses let each pixel see corrected neighbours: the result differs from s = 1.
  EXPECT_NE(synthesizeParallelCoordinates(mixed, {.subpassGrid = 1}, 0, 0, 40, 40).xy,
            synthesizeParallelCoordinates(mixed, {.subpassGrid = 2}, 0, 0, 40, 40).xy);
}

TEST(ParallelSynthesis, DoesNotDependOnThreadCountAndDependsOnSeed) {
  const ExemplarAnalysis& analysis = patternAnalysis();
  SourceCoordinates many = synthesizeParallelCoordinates(analysis, {}, 0, 0, 96, 80);
  SourceCoordinates one;
  {
    ThreadLimit limit(1);
    one = synthesizeParallelCoordinates(analysis, {}, 0, 0, 96, 80);
  }
  EXPECT_EQ(many.xy, one.xy);
  SourceCoordinates other = synthesizeParallelCoordinates(analysis, {.seed = 2}, 0, 0, 96, 80);
  EXPECT_NE(many.xy, other.xy);
}

TEST(ParallelSynthesis, CoordinatesStayInsideTheExemplar) {
  const ExemplarAnalysis& analysis = patternAnalysis();
  SourceCoordinates coords = synthesizeParallelCoordinates(analysis, {.defaultJitter = 1.5f}, -500, 300, 64, 48);
  ASSERT_EQ(coords.xy.size(), std::size_t(64 * 48 * 2));
  for (std::size_t i = 0; i < coords.xy.size(); i += 2) {
    ASSERT_GE(coords.xy[i], 0);
    ASSERT_LT(coords.xy[i], analysis.width);
    ASSERT_GE(coords.xy[i + 1], 0);
    ASSERT_LT(coords.xy[i + 1], analysis.height);
  }
}

TEST(ParallelSynthesis, ZeroJitterWithoutCorrectionIsPlainTiling) {
  const ExemplarAnalysis& analysis = patternAnalysis();
  SourceCoordinates coords = synthesizeParallelCoordinates(
      analysis, {.passes = 0, .defaultJitter = 0.0f, .coarsestFootprint = 0.0f}, -9, 4, 70, 50);
  // The upsampled start is S(p) = p + constant (mod m): a shifted tiling of the exemplar.
  const std::int32_t* origin = coords.at(-9, 4);
  for (int y = 4; y < 54; ++y)
    for (int x = -9; x < 61; ++x) {
      ASSERT_EQ(coords.at(x, y)[0], (origin[0] + x + 9) % analysis.width) << x << "," << y;
      ASSERT_EQ(coords.at(x, y)[1], (origin[1] + y - 4) % analysis.height) << x << "," << y;
    }
}

TEST(ParallelSynthesis, CorrectionLowersTheNeighborhoodDistance) {
  const ExemplarAnalysis& analysis = patternAnalysis();
  const int finest = analysis.levelCount() - 1;
  const double uncorrected =
      meanNeighborhoodDistance(analysis, finest, synthesizeParallelCoordinates(analysis, {.passes = 0}, 0, 0, 64, 64));
  const double corrected =
      meanNeighborhoodDistance(analysis, finest, synthesizeParallelCoordinates(analysis, {.passes = 2}, 0, 0, 64, 64));
  EXPECT_GT(uncorrected, 0.0);
  EXPECT_LT(corrected, 0.5 * uncorrected) << "uncorrected " << uncorrected << " corrected " << corrected;
  std::printf("mean neighborhood distance: uncorrected %.4f corrected %.4f\n", uncorrected, corrected);
}

TEST(ParallelSynthesis, RealExemplarIsFarLessPeriodicThanTiling) {
  auto path = gimpPattern("Stone/granite1.pat");
  TS_REQUIRE_DATA(path);
  Image exemplar = test::loadPatternRgb(*path, 48);
  ExemplarAnalysis analysis = analyzeExemplar(exemplar);
  Image out = synthesizeParallel(analysis, {}, 0, 0, 128, 128);
  MetricOptions metrics{.periodicitySamples = 500};
  const double synthesized = evaluateImage(exemplar, out, metrics).periodicity;
  const double tiled = evaluateImage(exemplar, exemplar.tiled(128, 128), metrics).periodicity;
  // A 48^2 crop is not tileable and gives little room to move: at the default jitter the
  // output keeps some repeats (~0.17 measured), but far fewer than tiling (1.0).
  EXPECT_LT(synthesized, 0.3 * tiled) << "synthesized " << synthesized << " tiled " << tiled;
  // Stronger jitter at the coarse levels breaks the repeats almost entirely (~0.03 measured).
  std::vector<float> strong(std::size_t(analysis.levelCount()), 0.4f);
  strong[0] = 1.0f, strong[1] = 0.7f;
  const double jittered =
      evaluateImage(exemplar, synthesizeParallel(analysis, {.jitter = strong}, 0, 0, 128, 128), metrics).periodicity;
  EXPECT_LT(jittered, 0.1);
}

// A GIMP pattern tiles, so from L&H 2005's tiled start the corrections keep a jittered tiling:
// a lattice of repeats. The random start at a level whose neighborhoods fit in the exemplar
// breaks it (leaves at 160^2: about 0.55 against 0.1).
TEST(ParallelSynthesis, RandomStartLeavesNoLattice) {
  auto path = gimpPattern("Plant/leaves.pat");
  TS_REQUIRE_DATA(path);
  const Image exemplar = test::loadPatternRgb(*path, 50);
  const ExemplarAnalysis analysis = analyzeExemplar(exemplar);
  auto latticeOf = [&](const ParallelSynthesisOptions& options) {
    return evaluateImage(exemplar, synthesizeParallel(analysis, options, 0, 0, 160, 160)).lattice;
  };
  const double tiledStart = latticeOf({.coarsestFootprint = 0.0f});
  const double randomStart = latticeOf({});
  EXPECT_LT(randomStart, 0.5 * tiledStart) << "random start " << randomStart << " tiled start " << tiledStart;
  EXPECT_LT(randomStart, 0.2);
  std::printf("lattice: tiled start %.3f, random start %.3f\n", tiledStart, randomStart);
}

// The share of pixels whose right neighbor continues their exemplar patch: how whole the
// output's patches are.
double continuedShare(const SourceCoordinates& coords, int exemplarWidth) {
  int continued = 0;
  for (int y = coords.y0; y < coords.y0 + coords.height; ++y)
    for (int x = coords.x0; x + 1 < coords.x0 + coords.width; ++x)
      continued += coords.at(x + 1, y)[0] == (coords.at(x, y)[0] + 1) % exemplarWidth &&
                   coords.at(x + 1, y)[1] == coords.at(x, y)[1];
  return double(continued) / (double(coords.width - 1) * coords.height);
}

// The continuation bias grows whole patches and keeps more of the exemplar (bark, 64^2 at 128^2:
// the share continued 0.60 -> 0.81 measured).
TEST(ParallelSynthesis, ContinuationBiasKeepsPatchesWhole) {
  auto path = gimpPattern("Wood/bark.pat");
  TS_REQUIRE_DATA(path);
  const Image exemplar = test::loadPatternRgb(*path, 64);
  const ExemplarAnalysis analysis = analyzeExemplar(exemplar);
  auto continued = [&](float bias) {
    return continuedShare(synthesizeParallelCoordinates(analysis, {.continuationBias = bias}, 0, 0, 128, 128),
                          analysis.width);
  };
  const double plain = continued(0.0f), biased = continued(0.4f);
  EXPECT_GT(biased, plain + 0.1) << "plain " << plain << " biased " << biased;
  std::printf("continued share: plain %.3f, biased %.3f\n", plain, biased);
}

TEST(ParallelSynthesis, StartsAtTheCoarsestLevelThatFitsTheExemplar) {
  const ExemplarAnalysis& analysis = patternAnalysis();  // 32^2, N = 5
  EXPECT_EQ(firstSynthesizedLevel(analysis, 0.0f), 0);
  const int first = firstSynthesizedLevel(analysis, 1.0f);
  EXPECT_LE(analysis.levels[first].neighborhoodSize * analysis.levels[first].spacing, 32);
  ASSERT_GT(first, 0);
  EXPECT_GT(analysis.levels[first - 1].neighborhoodSize * analysis.levels[first - 1].spacing, 32);
}

TEST(ParallelSynthesis, RejectsBadParameters) {
  const ExemplarAnalysis& analysis = patternAnalysis();
  test::expectParameterError([&] { synthesizeParallel(ExemplarAnalysis{}, {}, 0, 0, 8, 8); }, "analysis");
  test::expectParameterError([&] { synthesizeParallel(analysis, {}, 0, 0, 0, 8); }, "width");
  test::expectParameterError([&] { synthesizeParallel(analysis, {}, 0, 0, 8, -1); }, "height");
  test::expectParameterError([&] { synthesizeParallel(analysis, {}, 1 << 29, 0, 8, 8); }, "x0");
  test::expectParameterError([&] { synthesizeParallel(analysis, {.passes = -1}, 0, 0, 8, 8); }, "passes");
  test::expectParameterError([&] { synthesizeParallel(analysis, {.subpassGrid = 0}, 0, 0, 8, 8); }, "subpasses");
  test::expectParameterError([&] { synthesizeParallel(analysis, {.jitter = {0.4f}}, 0, 0, 8, 8); }, "jitter");
  test::expectParameterError([&] { synthesizeParallel(analysis, {.defaultJitter = -0.1f}, 0, 0, 8, 8); }, "jitter");
  test::expectParameterError([&] { synthesizeParallel(analysis, {.coarsestFootprint = -1.0f}, 0, 0, 8, 8); },
                             "coarsestFootprint");
  test::expectParameterError([&] { synthesizeParallel(analysis, {.startPasses = -1}, 0, 0, 8, 8); }, "startPasses");
  for (float bias : {-0.1f, 1.0f, std::nanf("")})
    test::expectParameterError([&] { synthesizeParallel(analysis, {.continuationBias = bias}, 0, 0, 8, 8); },
                               "continuationBias");
  std::vector<float> jitter(std::size_t(analysis.levelCount()), 0.4f);
  jitter[1] = std::nanf("");
  test::expectParameterError([&] { synthesizeParallel(analysis, {.jitter = jitter}, 0, 0, 8, 8); }, "jitter");
  SourceCoordinates coords(0, 0, 2, 2);
  test::expectParameterError([&] { lookupColors(Image{}, coords); }, "image");
  test::expectParameterError([&] { lookupColors(analysis.levels.back().image, coords, 9); }, "channels");
}

}  // namespace
}  // namespace texsynth
