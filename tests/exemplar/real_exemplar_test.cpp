// The analysis on a real exemplar (a GIMP pattern from gimp-data), cropped so it stays fast.
#include <gtest/gtest.h>

#include "exemplar_test_util.h"
#include "test_support.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/parallel.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/io/image_io.h"

using namespace texsynth;

TEST(RealExemplar, KdTreeMatchesBruteForceAndIsThreadIndependent) {
  auto path = gimpPattern("Stone/pink_marble.pat");
  TS_REQUIRE_DATA(path);
  Image exemplar = readImage(*path).crop(30, 40, 40, 40);
  AnalysisOptions options;
  options.similarCount = 5;
  options.search.nanoflannEpsilon = 0.0f;
  ExemplarAnalysis kdTree = analyzeExemplar(exemplar, options);
  options.search.backend = AnnBackend::BruteForce;
  ExemplarAnalysis bruteForce = analyzeExemplar(exemplar, options);
  ASSERT_EQ(kdTree.levelCount(), 5);
  for (int level = 0; level < kdTree.levelCount(); ++level) {
    EXPECT_GT(kdTree.levels[level].pca.keptEnergy, 0.5);
    EXPECT_EQ(kdTree.levels[level].similar, bruteForce.levels[level].similar) << "level " << level;
  }
  options.search = SimilarityOptions();
  ExemplarAnalysis one, two;
  {
    ThreadLimit limit(1);
    one = analyzeExemplar(exemplar, options);
  }
  {
    ThreadLimit limit(2);
    two = analyzeExemplar(exemplar, options);
  }
  test::expectIdenticalAnalyses(one, two);
}
