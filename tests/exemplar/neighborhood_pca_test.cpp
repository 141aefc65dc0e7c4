#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "exemplar_test_util.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/exemplar/neighborhood.h"
#include "texsynth/exemplar/pca.h"

using namespace texsynth;

TEST(Neighborhood, LayoutSpacingAndWrap) {
  Image image(10, 6, 2);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 10; ++x) {
      image.at(x, y, 0) = float(x);
      image.at(x, y, 1) = float(y);
    }
  NeighborhoodShape shape{3, 2, 2};
  std::vector<float> v(shape.dimension());
  gatherNeighborhood(image, 1, 0, shape, v.data());
  // Window rows y = -2, 0, 2 -> 4, 0, 2; columns x = -1, 1, 3 -> 9, 1, 3.
  const int xs[3] = {9, 1, 3}, ys[3] = {4, 0, 2};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(v[(j * 3 + i) * 2 + 0], float(xs[i]));
      EXPECT_EQ(v[(j * 3 + i) * 2 + 1], float(ys[j]));
    }
}

TEST(Neighborhood, BatchGatherEqualsSingleGather) {
  Image image = test::makeTestPattern(13, 9);
  NeighborhoodShape shape{5, 4, 3};
  std::vector<float> batch(image.pixelCount() * shape.dimension()), single(shape.dimension());
  gatherNeighborhoods(image, 0, std::int64_t(image.pixelCount()), shape, batch.data());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      gatherNeighborhood(image, x, y, shape, single.data());
      const float* stored = &batch[(std::size_t(y) * image.width + x) * shape.dimension()];
      for (int i = 0; i < shape.dimension(); ++i) ASSERT_EQ(stored[i], single[i]) << x << "," << y << " #" << i;
    }
}

TEST(Pca, KeptEnergyGrowsWithDimensionsUpToOne) {
  Image image = test::makeTestPattern(32, 32, 3);
  NeighborhoodShape shape{5, 1, 3};
  double previous = 0;
  for (int d : {1, 2, 5, 10, 20, 40, 75}) {
    PcaBasis pca = fitNeighborhoodPca(image, shape, d);
    EXPECT_EQ(pca.outputDimension, d);
    EXPECT_GT(pca.keptEnergy, 0.0);
    EXPECT_LE(pca.keptEnergy, 1.0);
    EXPECT_GT(pca.keptEnergy, previous) << "D=" << d;
    previous = pca.keptEnergy;
  }
  EXPECT_NEAR(previous, 1.0, 1e-6);  // all 75 axes keep everything
  PcaBasis capped = fitNeighborhoodPca(image, shape, 500);
  EXPECT_EQ(capped.outputDimension, 75);
  EXPECT_THROW(fitNeighborhoodPca(image, shape, 0), ParameterError);
}

TEST(Pca, BasisIsOrthonormalWithDescendingVariances) {
  Image image = test::makeTestPattern(24, 24, 4);
  PcaBasis pca = fitNeighborhoodPca(image, {3, 2, 3}, 8);
  for (int a = 0; a < pca.outputDimension; ++a) {
    if (a > 0) {
      EXPECT_LE(pca.variances[a], pca.variances[a - 1]);
    }
    for (int b = 0; b < pca.outputDimension; ++b) {
      double dot = 0;
      for (int j = 0; j < pca.inputDimension; ++j) dot += double(pca.component(a, j)) * pca.component(b, j);
      EXPECT_NEAR(dot, a == b ? 1.0 : 0.0, 1e-5);
    }
  }
}

TEST(Pca, ProjectedVarianceMatchesEigenvalue) {
  Image image = test::makeTestPattern(32, 32, 9);
  NeighborhoodShape shape{5, 2, 3};
  PcaBasis pca = fitNeighborhoodPca(image, shape, 4);
  std::vector<float> projected = projectAllNeighborhoods(image, shape, pca);
  for (int axis = 0; axis < 4; ++axis) {
    double mean = 0, square = 0;
    for (std::size_t p = 0; p < image.pixelCount(); ++p) {
      mean += projected[p * 4 + axis];
      square += double(projected[p * 4 + axis]) * projected[p * 4 + axis];
    }
    mean /= double(image.pixelCount());
    EXPECT_NEAR(mean, 0.0, 1e-4);
    EXPECT_NEAR(square / double(image.pixelCount()), pca.variances[axis], 1e-3 * pca.variances[0]);
  }
}

TEST(Pca, PublicProjectionEqualsStoredVectorsBitwise) {
  Image exemplar = test::makeTestPattern(32, 32, 2);
  AnalysisOptions options;
  options.neighborhoodSize = 7;
  options.pcaDimensions = 12;
  options.featureMask = test::makeBlobMask(32, 32);
  ExemplarAnalysis analysis = analyzeExemplar(exemplar, options);
  for (int level = 0; level < analysis.levelCount(); ++level) {
    const ExemplarLevel& stored = analysis.levels[level];
    NeighborhoodShape shape = analysis.shape(level);
    ASSERT_EQ(shape.channels, 4);
    std::vector<float> neighborhood(shape.dimension()), projected(stored.pca.outputDimension);
    for (auto [x, y] : {std::pair{0, 0}, {31, 31}, {5, 17}, {30, 1}}) {
      gatherNeighborhood(stored.image, x, y, shape, neighborhood.data());
      stored.pca.project(neighborhood.data(), projected.data());
      const float* expected = stored.projectedAt(analysis.pixelIndex(x, y));
      for (int i = 0; i < stored.pca.outputDimension; ++i)
        ASSERT_EQ(projected[i], expected[i]) << "level " << level << " pixel " << x << "," << y;
    }
  }
}
