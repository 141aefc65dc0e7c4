#include "texsynth/exemplar/analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "exemplar_test_util.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

using namespace texsynth;

namespace {

// Records stage names and checks that advances stay within each stage's total.
class RecordingProgress : public Progress {
 public:
  void begin(const std::string& stage, std::int64_t total) override {
    stages.push_back(stage);
    total_ = total;
    done_ = 0;
  }
  void advance(std::int64_t units) override {
    throwIfCancelled();
    done_ += units;
    EXPECT_LE(done_, total_) << stages.back();
  }
  void end() override { EXPECT_EQ(done_, total_) << stages.back(); }
  std::vector<std::string> stages;

 private:
  std::int64_t total_ = 0, done_ = 0;
};

class CancelAfterStages : public RecordingProgress {
 public:
  void begin(const std::string& stage, std::int64_t total) override {
    RecordingProgress::begin(stage, total);
    if (stages.size() == 3) cancel();
  }
};

}  // namespace

TEST(Analysis, LevelsHaveTheDocumentedShape) {
  Image exemplar = test::makeTestPattern(32, 16);
  AnalysisOptions options;
  options.similarCount = 3;
  options.featureMask = test::makeBlobMask(32, 16);
  ExemplarAnalysis analysis = analyzeExemplar(exemplar, options);
  ASSERT_EQ(analysis.levelCount(), 4);
  EXPECT_TRUE(analysis.hasFeatureChannel);
  EXPECT_EQ(analysis.channels(), 4);
  EXPECT_EQ(analysis.exclusionRadius, 2);
  for (int l = 0; l < 4; ++l) {
    const ExemplarLevel& level = analysis.levels[l];
    EXPECT_EQ(level.spacing, 8 >> l);
    EXPECT_EQ(level.image.channels, 4);
    EXPECT_EQ(level.pca.inputDimension, 5 * 5 * 4);
    EXPECT_EQ(level.pca.outputDimension, 20);
    EXPECT_EQ(level.projected.size(), 32u * 16u * 20u);
    EXPECT_EQ(level.similar.size(), 32u * 16u * 3u);
    EXPECT_EQ(analysis.similarAt(l, 77)[0], 77);
  }
  // The finest level is the exemplar plus its feature channel.
  const Image& finest = analysis.levels.back().image;
  EXPECT_EQ(finest.at(5, 6, 1), exemplar.at(5, 6, 1));
  EXPECT_NE(finest.at(5, 6, 3), 0.0f);
}

TEST(Analysis, IdenticalForOneAndTwoThreads) {
  for (AnnBackend backend : {AnnBackend::Nanoflann, AnnBackend::FaissHnsw}) {
    // HNSW in Debian's FAISS is slow to build: a smaller exemplar keeps the test fast.
    const int width = backend == AnnBackend::FaissHnsw ? 24 : 48, height = backend == AnnBackend::FaissHnsw ? 20 : 40;
    Image exemplar = test::makeTestPattern(width, height, 5);
    AnalysisOptions options;
    options.similarCount = 4;
    options.search.backend = backend;
    options.featureMask = test::makeBlobMask(width, height);
    ExemplarAnalysis one, two;
    {
      ThreadLimit limit(1);
      one = analyzeExemplar(exemplar, options);
    }
    {
      ThreadLimit limit(2);
      two = analyzeExemplar(exemplar, options);
    }
    SCOPED_TRACE(annBackendName(backend));
    test::expectIdenticalAnalyses(one, two);
  }
}

TEST(Analysis, ReportsEveryStageAndHonoursCancel) {
  Image exemplar = test::makeTestPattern(16, 16);
  RecordingProgress progress;
  analyzeExemplar(exemplar, {}, progress);
  // Stack, then PCA and similarity sets for each of the 4 levels.
  ASSERT_EQ(progress.stages.size(), 9u);
  EXPECT_EQ(progress.stages[0], "exemplar: Gaussian stack");
  EXPECT_EQ(progress.stages[8], "exemplar: similarity sets (level 4/4)");
  AnalysisOptions selfOnly;  // k = 1 skips the search but still completes its stages
  selfOnly.similarCount = 1;
  RecordingProgress quiet;
  analyzeExemplar(exemplar, selfOnly, quiet);
  EXPECT_EQ(quiet.stages.size(), 9u);
  CancelAfterStages cancelling;
  EXPECT_THROW(analyzeExemplar(exemplar, {}, cancelling), Cancelled);
}

TEST(Analysis, NeighborhoodSizePerLevelCoarsestFirstLastRepeating) {
  AnalysisOptions options;
  options.levelNeighborhoodSizes = {3, 7};
  ExemplarAnalysis analysis = analyzeExemplar(test::makeTestPattern(32, 32), options);
  ASSERT_GE(analysis.levelCount(), 3);
  for (int level = 0; level < analysis.levelCount(); ++level) {
    const int n = level == 0 ? 3 : 7;
    EXPECT_EQ(analysis.levels[level].neighborhoodSize, n);
    EXPECT_EQ(neighborhoodSizeAt(options, level), n);
    EXPECT_EQ(analysis.levels[level].pca.inputDimension, n * n * 3);
  }
}

TEST(Analysis, RejectsBadParameters) {
  Image exemplar = test::makeTestPattern(16, 16);
  auto expectParameterError = [&](const AnalysisOptions& options, const std::string& parameter) {
    try {
      analyzeExemplar(exemplar, options);
      ADD_FAILURE() << "no error for " << parameter;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.parameter(), parameter);
    }
  };
  AnalysisOptions even;
  even.neighborhoodSize = 4;
  expectParameterError(even, "neighborhoodSize");
  AnalysisOptions evenLevel;
  evenLevel.levelNeighborhoodSizes = {3, 6};
  expectParameterError(evenLevel, "levelNeighborhoodSizes");
  AnalysisOptions noDims;
  noDims.pcaDimensions = 0;
  expectParameterError(noDims, "pcaDimensions");
  AnalysisOptions noSimilar;
  noSimilar.similarCount = 0;
  expectParameterError(noSimilar, "similarCount");
  AnalysisOptions tooManyLevels;
  tooManyLevels.levelCount = 5;
  expectParameterError(tooManyLevels, "levelCount");
  AnalysisOptions wrongMask;
  wrongMask.featureMask = test::makeBlobMask(16, 15);
  expectParameterError(wrongMask, "featureMask");
  AnalysisOptions badWeight;
  badWeight.featureMask = test::makeBlobMask(16, 16);
  badWeight.featureWeight = -2.0f;
  expectParameterError(badWeight, "featureWeight");
  AnalysisOptions bigRadius;
  bigRadius.exclusionRadius = 8;
  expectParameterError(bigRadius, "similarCount");
  EXPECT_THROW(analyzeExemplar(Image(), {}), ParameterError);
  Image withNaN = exemplar;
  withNaN.pixels[7] = std::nanf("");
  EXPECT_THROW(analyzeExemplar(withNaN, {}), ParameterError);
}
