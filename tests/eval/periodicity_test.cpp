// Periodicity: tilings repeat at one offset, noise and textures do not.
#include "texsynth/eval/periodicity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "eval_test_images.h"
#include "test_support.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

using test::scaled;

TEST(Periodicity, TilingIsPeriodic) {
  Image tile = scaled(test::makeTestPattern(64, 64, 7), 255);
  PatchIndex index(tile.tiled(160, 128), 7);
  // Every patch repeats at (64, 0) or its opposite; only ones with no room either side miss.
  EXPECT_GT(periodicity(index), 0.9);
}

TEST(Periodicity, NoiseAndAperiodicTextureAreNot) {
  EXPECT_EQ(periodicity(PatchIndex(scaled(test::noise(128, 128, 3), 255), 7)), 0.0);
  EXPECT_LT(periodicity(PatchIndex(scaled(test::makeTestPattern(128, 128, 3), 255), 7)), 0.05);
}

TEST(Periodicity, OverlappingRepeatsDoNotCount) {
  // A flat image duplicates everywhere, but the most common period must still be one that
  // lies outside the overlap window: every sample has some, so the share is 1.
  PatchIndex flat(Image(40, 40, 3, 128.0f), 7);
  EXPECT_DOUBLE_EQ(periodicity(flat), 1.0);
  // Too small to hold a non-overlapping duplicate: nothing counts.
  PatchIndex tiny(Image(12, 12, 3, 128.0f), 7);
  EXPECT_EQ(periodicity(tiny), 0.0);
}

TEST(Periodicity, ThresholdDecidesDuplicates) {
  Image tile = scaled(test::makeTestPattern(40, 40, 2), 255);
  Image image = tile.tiled(80, 40);
  for (int y = 0; y < 40; ++y)
    for (int x = 40; x < 80; ++x) image.at(x, y, 1) += 3.0f;  // the copy is off by 3 in green
  PatchIndex index(image, 7);
  // Mean squared difference per value of a copy: 3^2 / 3 channels = 3.
  EXPECT_GT(periodicity(index, {500, 4.0, 1}), 0.3);
  EXPECT_EQ(periodicity(index, {500, 2.0, 1}), 0.0);
}

TEST(Periodicity, DeterministicAcrossThreadsAndSeeded) {
  Image image = scaled(test::makeTestPattern(50, 50, 5).tiled(130, 120), 255);
  for (int i = 0; i < 40; ++i) image.at((i * 37) % 130, (i * 53) % 120, 0) += 60;  // break some repeats
  PatchIndex index(image, 7);
  double one, two;
  {
    ThreadLimit limit(1);
    one = periodicity(index, {300, 4.0, 9});
  }
  {
    ThreadLimit limit(2);
    two = periodicity(index, {300, 4.0, 9});
  }
  EXPECT_EQ(one, two);
  EXPECT_EQ(periodicity(index, {300, 4.0, 9}), periodicity(index, {300, 4.0, 9}));
}

TEST(Periodicity, RejectsBadOptions) {
  PatchIndex index(Image(20, 20, 3), 5);
  EXPECT_THROW(periodicity(index, {0, 4.0, 1}), ParameterError);
  EXPECT_THROW(periodicity(index, {10, -1.0, 1}), ParameterError);
  EXPECT_THROW(periodicity(index, {10, std::nan(""), 1}), ParameterError);
}

}  // namespace
}  // namespace texsynth
