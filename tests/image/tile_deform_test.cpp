#include "texsynth/image/tile_deform.h"

#include <gtest/gtest.h>

#include <cmath>

#include "image_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

TEST(TileDeform, WindowIsBitIdenticalToTheSameRegionOfALargerOutput) {
  Image exemplar = test::makeTestPattern(48, 40);
  TileDeformOptions options{.seed = 9};
  Image large = synthesizeTileDeform(exemplar, options, -50, -30, 200, 160);
  Image window = synthesizeTileDeform(exemplar, options, 37, 11, 61, 43);
  EXPECT_EQ(window.pixels, large.crop(87, 41, 61, 43).pixels);
  // Single points agree with the window too.
  TileDeformTexture texture(exemplar, options);
  float color[3];
  texture.sample(37 + 5 + 0.5, 11 + 7 + 0.5, color);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(color[c], window.at(5, 7, c));
}

TEST(TileDeform, ZeroLambdaReproducesPlainTilingExactly) {
  Image exemplar = test::makeTestPattern(32, 24);
  Image out = synthesizeTileDeform(exemplar, {.lambdaX = 0, .lambdaY = 0}, 0, 0, 100, 70);
  EXPECT_EQ(out.pixels, exemplar.tiled(100, 70).pixels);
}

TEST(TileDeform, DeformsAndDoesNotDependOnThreadCount) {
  Image exemplar = test::makeTestPattern(32, 32);
  Image many = synthesizeTileDeform(exemplar, {}, 0, 0, 128, 96);
  Image one;
  {
    ThreadLimit limit(1);
    one = synthesizeTileDeform(exemplar, {}, 0, 0, 128, 96);
  }
  EXPECT_EQ(one.pixels, many.pixels);
  EXPECT_NE(many.pixels, exemplar.tiled(128, 96).pixels);
  EXPECT_NE(many.pixels, synthesizeTileDeform(exemplar, {.seed = 2}, 0, 0, 128, 96).pixels);
}

TEST(TileDeform, DisplacementIsClampedAndDirectionLimited) {
  Image exemplar = test::makeTestPattern(32, 32);
  TileDeformTexture clamped(exemplar,
                            {.cellWidth = 10, .cellHeight = 20, .lambdaX = 5, .lambdaY = 5, .maxDisplacement = 0.3f});
  bool reachedLimit = false;
  for (int i = -20; i < 20; ++i)
    for (int j = -20; j < 20; ++j) {
      float d[2];
      clamped.cornerDisplacement(i, j, d);
      EXPECT_LE(std::abs(d[0]), 3.0f + 1e-5f);
      EXPECT_LE(std::abs(d[1]), 6.0f + 1e-5f);
      reachedLimit |= std::abs(d[0]) > 2.99f;
    }
  EXPECT_TRUE(reachedLimit);
  TileDeformTexture xOnly(exemplar, {.lambdaX = 0.5f, .lambdaY = 0.5f, .directions = DeformDirections::XOnly});
  TileDeformTexture yOnly(exemplar, {.lambdaX = 0.5f, .lambdaY = 0.5f, .directions = DeformDirections::YOnly});
  double xMoved = 0, yMoved = 0;
  for (int k = 0; k < 200; ++k) {
    double p[2], q[2], x = k * 3.7 + 0.5, y = k * 1.3 + 0.5;
    xOnly.sourcePosition(x, y, p);
    yOnly.sourcePosition(x, y, q);
    EXPECT_EQ(p[1], y);
    EXPECT_EQ(q[0], x);
    xMoved += std::abs(p[0] - x), yMoved += std::abs(q[1] - y);
  }
  EXPECT_GT(xMoved, 100.0);
  EXPECT_GT(yMoved, 100.0);
}

TEST(TileDeform, RejectsBadParameters) {
  Image exemplar = test::makeTestPattern(16, 16);
  auto expectRejected = [&](const TileDeformOptions& options, const std::string& parameter) {
    test::expectParameterError([&] { synthesizeTileDeform(exemplar, options, 0, 0, 8, 8); }, parameter);
  };
  expectRejected({.cellWidth = -1}, "cellWidth");
  expectRejected({.cellHeight = NAN}, "cellHeight");
  expectRejected({.lambdaX = -0.1f}, "lambdaX");
  expectRejected({.lambdaY = INFINITY}, "lambdaY");
  expectRejected({.maxDisplacement = -1}, "maxDisplacement");
  expectRejected({.maxDisplacement = 0.5f}, "maxDisplacement");  // cells could fold, as in 3D
  expectRejected({.noiseFrequency = 0}, "noiseFrequency");
  EXPECT_THROW(synthesizeTileDeform(Image(), {}, 0, 0, 8, 8), ParameterError);
  EXPECT_THROW(synthesizeTileDeform(exemplar, {}, 0, 0, 0, 8), ParameterError);
  // Far from the origin, positions stop resolving pixels: the window rule of every random-access method.
  test::expectParameterError([&] { synthesizeTileDeform(exemplar, {}, std::int64_t(1) << 58, 0, 8, 8); }, "x0");
  test::expectParameterError([&] { synthesizeTileDeform(exemplar, {}, 0, -(std::int64_t(1) << 28), 8, 8); }, "y0");
}

TEST(TileDeform, RealExemplarIsFarLessPeriodicThanTiling) {
  auto path = gimpPattern("Stone/granite1.pat");
  TS_REQUIRE_DATA(path);
  Image exemplar = test::loadPatternRgb(*path, 128);
  double tiling = test::periodicityOf(exemplar.tiled(256, 256));
  double deformed = test::periodicityOf(synthesizeTileDeform(exemplar, {}, 0, 0, 256, 256));
  EXPECT_GT(tiling, 0.5);
  EXPECT_LT(deformed, 0.5 * tiling) << "tiling " << tiling;
}

}  // namespace
}  // namespace texsynth
