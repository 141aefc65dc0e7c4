// Distinctive colors: the pixels farther from the median color than all but a share of them, and
// the feature mask made of them.
#include "texsynth/exemplar/distinctive_colors.h"

#include <gtest/gtest.h>

#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

// A flat gray ground with dark one-pixel lines every 8th column: 1/8 of the pixels.
Image linedImage() {
  Image image(32, 24, 3, 0.6f);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; x += 8)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = 0.1f;
  return image;
}

TEST(DistinctiveColors, AFlatGroundsSparseFeaturesAreExactlyItsDistinctivePixels) {
  const Image image = linedImage();
  const Image mask = distinctiveFeatureMask(image, 20);
  ASSERT_EQ(mask.width, image.width);
  ASSERT_EQ(mask.height, image.height);
  ASSERT_EQ(mask.channels, 1);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) EXPECT_EQ(mask.at(x, y, 0), x % 8 == 0 ? 1.0f : 0.0f) << x << "," << y;
}

TEST(DistinctiveColors, OnASmoothRangeTheShareIsThePercent) {
  // Values spread evenly around their median: the fifth farthest from it are distinctive.
  Image image(100, 10, 1);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) image.at(x, y, 0) = float(x) / 99.0f + 0.0001f * float(y);
  const DistinctiveColors distinctive(image, 1, 20);
  int count = 0;
  for (std::size_t p = 0; p < image.pixelCount(); ++p) count += distinctive(image.pixels.data() + p);
  EXPECT_NEAR(count, 200, 10);
  const float middle = 0.5f, end = 0.0f;
  EXPECT_FALSE(distinctive(&middle));
  EXPECT_TRUE(distinctive(&end));
}

TEST(DistinctiveColors, AFlatImageHasNoFeatureMask) {
  EXPECT_TRUE(distinctiveFeatureMask(Image(16, 16, 3, 0.4f), 20).empty());
}

TEST(DistinctiveColors, BadArgumentsAreRefused) {
  EXPECT_THROW(DistinctiveColors(Image(), 3, 20), ParameterError);
  EXPECT_THROW(DistinctiveColors(linedImage(), 4, 20), ParameterError);
  EXPECT_THROW(DistinctiveColors(linedImage(), 3, 101), ParameterError);
}

}  // namespace
}  // namespace texsynth
