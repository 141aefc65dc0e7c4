#include "texsynth/image/color_histogram_cost.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

// A 4x4 gray image: the top row dark (0.1), the rest light (0.9), one channel per color.
Image twoToneImage() {
  Image image(4, 4, 3);
  for (std::size_t p = 0; p < image.pixelCount(); ++p)
    for (int c = 0; c < 3; ++c) image.pixels[p * 3 + std::size_t(c)] = p < 4 ? 0.1f : 0.9f;
  return image;
}

TEST(ColorHistogramCost, ZeroWhereTheOutputMatchesTheExemplar) {
  const Image image = twoToneImage();
  // Every pixel used once: the output's histogram is the exemplar's.
  std::vector<std::int32_t> sources(16);
  for (std::int32_t p = 0; p < 16; ++p) sources[std::size_t(p)] = p;
  const detail::ColorHistogramCost cost(image, 3, sources);
  ASSERT_TRUE(cost.active());
  for (std::int32_t p = 0; p < 16; ++p) EXPECT_NEAR(cost.cost(p), 0.0f, 1e-2f) << p;
}

TEST(ColorHistogramCost, FavorsTheColorsTheOutputLacks) {
  const Image image = twoToneImage();
  // Only light pixels used: the dark quarter of the exemplar is missing from the output.
  const std::vector<std::int32_t> sources(40, 5);
  const detail::ColorHistogramCost cost(image, 3, sources);
  EXPECT_NEAR(cost.cost(0), -1.0f, 1e-2f);  // dark: absent, as cheap as the term makes anything
  // light: 100% of the output against 75% of the exemplar
  EXPECT_NEAR(cost.cost(8), 1.0f / 0.75f - 1.0f, 1e-2f);
  // Over-use is clamped: only dark pixels used (4x their share).
  const detail::ColorHistogramCost dark(image, 3, std::vector<std::int32_t>(10, 1));
  EXPECT_FLOAT_EQ(dark.cost(1), 2.0f);
}

TEST(ColorHistogramCost, InactiveWithoutSourcesAndRefusesStrayPixels) {
  const Image image = twoToneImage();
  EXPECT_FALSE(detail::ColorHistogramCost(image, 3, {}).active());
  EXPECT_FALSE(detail::ColorHistogramCost().active());
  const std::vector<std::int32_t> stray{16};
  EXPECT_THROW(detail::ColorHistogramCost(image, 3, stray), ParameterError);
}

}  // namespace
}  // namespace texsynth
