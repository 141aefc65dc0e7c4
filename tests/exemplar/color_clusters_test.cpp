// Colour quantization for gradient synthesis: clusters, their regions, determinism.
#include "texsynth/exemplar/color_clusters.h"

#include <gtest/gtest.h>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

// Four flat colour bands.
Image bands() {
  Image image(32, 32, 3);
  const float colors[4][3] = {{0.1f, 0.1f, 0.1f}, {0.9f, 0.1f, 0.1f}, {0.1f, 0.9f, 0.1f}, {0.9f, 0.9f, 0.9f}};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = colors[x / 8][c];
  return image;
}

TEST(ColorClusters, FindsFlatColoursExactly) {
  const ColorClusters clusters = clusterColors(bands(), 4);
  EXPECT_EQ(clusters.count, 4);
  EXPECT_NEAR(clusters.meanSquaredError, 0.0, 1e-9);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      EXPECT_EQ(clusters.labels[std::size_t(y * 32 + x)], clusters.labels[std::size_t(x / 8 * 8)]);
}

TEST(ColorClusters, ClustersNeverSpanTwoRegions) {
  // Regions cut across the colour bands: the left half of every band is region 1.
  std::vector<std::uint8_t> regions(32 * 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) regions[std::size_t(y * 32 + x)] = x % 8 < 4 ? 1 : 0;
  const ColorClusters clusters = clusterColors(bands(), 8, regions);
  for (std::size_t p = 0; p < regions.size(); ++p) EXPECT_EQ(clusters.regions[clusters.labels[p]], regions[p]);
  EXPECT_NEAR(clusters.meanSquaredError, 0.0, 1e-9);  // 4 colours x 2 regions
}

TEST(ColorClusters, MoreClustersLowerTheError) {
  EXPECT_GT(clusterColors(bands(), 2).meanSquaredError, clusterColors(bands(), 3).meanSquaredError);
}

TEST(ColorClusters, RejectsBadArguments) {
  EXPECT_THROW(clusterColors(Image(), 4), ParameterError);
  EXPECT_THROW(clusterColors(bands(), 0), ParameterError);
  EXPECT_THROW(clusterColors(bands(), 4, std::vector<std::uint8_t>(5)), ParameterError);
  std::vector<std::uint8_t> twoRegions(32 * 32, 0);
  twoRegions[0] = 1;
  EXPECT_THROW(clusterColors(bands(), 1, twoRegions), ParameterError);
}

}  // namespace
}  // namespace texsynth
