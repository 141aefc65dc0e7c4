#pragma once
// Helpers shared by the exemplar tests.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/exemplar/analysis.h"

namespace texsynth::test {

template <typename T>
bool bitwiseEqual(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Every stored number of two analyses, compared bit for bit.
inline void expectIdenticalAnalyses(const ExemplarAnalysis& a, const ExemplarAnalysis& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.colorChannels, b.colorChannels);
  ASSERT_EQ(a.hasFeatureChannel, b.hasFeatureChannel);
  ASSERT_EQ(a.neighborhoodSize, b.neighborhoodSize);
  ASSERT_EQ(a.similarCount, b.similarCount);
  ASSERT_EQ(a.exclusionRadius, b.exclusionRadius);
  ASSERT_EQ(a.levelCount(), b.levelCount());
  for (int l = 0; l < a.levelCount(); ++l) {
    const ExemplarLevel &x = a.levels[l], &y = b.levels[l];
    SCOPED_TRACE("level " + std::to_string(l));
    EXPECT_EQ(x.spacing, y.spacing);
    EXPECT_EQ(x.neighborhoodSize, y.neighborhoodSize);
    EXPECT_EQ(x.image.channels, y.image.channels);
    EXPECT_TRUE(bitwiseEqual(x.image.pixels, y.image.pixels));
    EXPECT_EQ(x.pca.inputDimension, y.pca.inputDimension);
    EXPECT_EQ(x.pca.outputDimension, y.pca.outputDimension);
    EXPECT_TRUE(bitwiseEqual(x.pca.mean, y.pca.mean));
    EXPECT_TRUE(bitwiseEqual(x.pca.basis, y.pca.basis));
    EXPECT_TRUE(bitwiseEqual(x.pca.variances, y.pca.variances));
    EXPECT_EQ(x.pca.keptEnergy, y.pca.keptEnergy);
    EXPECT_EQ(x.pca.totalVariance, y.pca.totalVariance);
    EXPECT_TRUE(bitwiseEqual(x.projected, y.projected));
    EXPECT_TRUE(bitwiseEqual(x.similar, y.similar));
  }
}

// A binary mask with a few blobs, for feature-channel tests.
inline Image makeBlobMask(int width, int height) {
  Image mask(width, height, 1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      bool blob = ((x / 5) + (y / 7)) % 3 == 0 && (x % 5) < 3;
      mask.at(x, y, 0) = blob ? 1.0f : 0.0f;
    }
  return mask;
}

}  // namespace texsynth::test
