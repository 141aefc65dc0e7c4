#include "texsynth/image/make_tileable.h"

#include <gtest/gtest.h>

#include "image_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"

namespace texsynth {
namespace {

// A non-tileable exemplar: a smooth gradient plus texture, so opposite borders differ.
Image nonTileable() {
  Image image = test::makeTestPattern(80, 64, 2);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = 0.6f * image.at(x, y, c) + 0.4f * float(x + y) / 144.0f;
  return image;
}

TEST(MakeTileable, HidesTheWrapSeams) {
  Image exemplar = nonTileable();
  SeamStrength before = measureSeams(exemplar);
  Image tileable = makeTileable(exemplar);
  SeamStrength after = measureSeams(tileable);
  EXPECT_EQ(tileable.width, 80 - 12);
  EXPECT_EQ(tileable.height, 64 - 10);
  EXPECT_GT(before.ratio(), 3.0);
  EXPECT_LT(after.ratio(), 1.5);
  EXPECT_LT(after.ratio(), 0.3 * before.ratio());
}

TEST(MakeTileable, HidesSeamsOfARealPatternCrop) {
  auto path = gimpPattern("Stone/marble1.pat");
  TS_REQUIRE_DATA(path);
  // A crop of a tileable pattern is not tileable.
  Image exemplar = test::loadPatternRgb(*path, 200).crop(10, 20, 100, 90);
  SeamStrength before = measureSeams(exemplar), after = measureSeams(makeTileable(exemplar));
  EXPECT_LT(after.ratio(), 0.75 * before.ratio()) << before.ratio() << " -> " << after.ratio();
  EXPECT_LT(after.ratio(), 1.2);
}

TEST(MakeTileable, RejectsBadParameters) {
  Image exemplar = nonTileable();
  EXPECT_THROW(makeTileable(exemplar, {.overlapFraction = 0}), ParameterError);
  EXPECT_THROW(makeTileable(exemplar, {.overlapFraction = 0.6f}), ParameterError);
  EXPECT_THROW(makeTileable(exemplar, {.featherRadius = -1}), ParameterError);
  EXPECT_THROW(makeTileable(test::makeTestPattern(8, 8)), ParameterError);
  EXPECT_THROW(measureSeams(Image(1, 1, 3)), ParameterError);
}

}  // namespace
}  // namespace texsynth
