#include "texsynth/image/tile_blend.h"

#include <gtest/gtest.h>

#include "image_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/eval/histogram_distance.h"

namespace texsynth {
namespace {

TEST(TileBlend, WindowIsBitIdenticalToTheSameRegionOfALargerOutput) {
  Image exemplar = test::makeTestPattern(48, 40);
  TileBlendOptions options{.seed = 4};
  Image large = synthesizeTileBlend(exemplar, options, -40, -20, 180, 150);
  Image window = synthesizeTileBlend(exemplar, options, 13, 29, 57, 33);
  EXPECT_EQ(window.pixels, large.crop(53, 49, 57, 33).pixels);
}

TEST(TileBlend, DoesNotDependOnThreadCount) {
  Image exemplar = test::makeTestPattern(32, 32);
  Image many = synthesizeTileBlend(exemplar, {}, 0, 0, 96, 80);
  Image one;
  {
    ThreadLimit limit(1);
    one = synthesizeTileBlend(exemplar, {}, 0, 0, 96, 80);
  }
  EXPECT_EQ(one.pixels, many.pixels);
  EXPECT_NE(many.pixels, synthesizeTileBlend(exemplar, {.seed = 2}, 0, 0, 96, 80).pixels);
}

TEST(TileBlend, PreservesTheExemplarHistogram) {
  Image exemplar = test::makeTestPattern(64, 64, 5);
  Image out = synthesizeTileBlend(exemplar, {}, 0, 0, 256, 256);
  // A linear cross-fade (same tiles, no Gaussian-space blend) shrinks the variance and moves
  // the histogram much more.
  double blended = histogramDistance(exemplar, out);
  EXPECT_LT(blended, 0.02);
  Image washed = exemplar.tiled(256, 256);
  for (float& v : washed.pixels) v = 0.5f * v + 0.25f;
  EXPECT_GT(histogramDistance(exemplar, washed), 3 * blended);
}

TEST(TileBlend, RejectsBadParameters) {
  Image exemplar = test::makeTestPattern(16, 16);
  auto expectRejected = [&](const TileBlendOptions& options, const std::string& parameter) {
    test::expectParameterError([&] { synthesizeTileBlend(exemplar, options, 0, 0, 8, 8); }, parameter);
  };
  expectRejected({.tileSize = -3}, "tileSize");
  expectRejected({.weightExponent = 0.5f}, "weightExponent");
  expectRejected({.gaussianization = {.lutSize = 0}}, "lutSize");
  EXPECT_THROW(synthesizeTileBlend(Image(), {}, 0, 0, 8, 8), ParameterError);
  EXPECT_THROW(synthesizeTileBlend(exemplar, {}, 0, 0, 8, -1), ParameterError);
  test::expectParameterError([&] { synthesizeTileBlend(exemplar, {}, std::int64_t(1) << 58, 0, 8, 8); }, "x0");
}

TEST(TileBlend, RealExemplarIsFarLessPeriodicThanTiling) {
  auto path = gimpPattern("Stone/granite1.pat");
  TS_REQUIRE_DATA(path);
  Image exemplar = test::loadPatternRgb(*path, 128);
  double tiling = test::periodicityOf(exemplar.tiled(256, 256));
  Image blended = synthesizeTileBlend(exemplar, {}, 0, 0, 256, 256);
  EXPECT_LT(test::periodicityOf(blended), 0.5 * tiling);
  EXPECT_LT(histogramDistance(exemplar, blended), 0.02);
}

}  // namespace
}  // namespace texsynth
