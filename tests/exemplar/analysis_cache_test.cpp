#include "texsynth/exemplar/analysis_cache.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "exemplar_test_util.h"
#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"

using namespace texsynth;
namespace fs = std::filesystem;

namespace {

AnalysisOptions smallOptions() {
  AnalysisOptions options;
  options.similarCount = 3;
  options.featureMask = test::makeBlobMask(24, 24);
  return options;
}

}  // namespace

TEST(AnalysisCache, MissWritesFileAndHitReturnsIdenticalData) {
  test::TempDir dir;
  Image exemplar = test::makeTestPattern(24, 24);
  AnalysisOptions options = smallOptions();
  const std::string cacheDir = dir.file("cache");  // created on demand
  ExemplarAnalysis fresh = analyzeExemplarCached(exemplar, options, cacheDir);
  const std::uint64_t key = analysisCacheKey(exemplar, options);
  const std::string path = analysisCachePath(cacheDir, key);
  ASSERT_TRUE(fs::exists(path));
  test::expectIdenticalAnalyses(fresh, analyzeExemplar(exemplar, options));

  auto loaded = loadCachedAnalysis(path, key);
  ASSERT_TRUE(loaded.has_value());
  test::expectIdenticalAnalyses(*loaded, fresh);
  test::expectIdenticalAnalyses(analyzeExemplarCached(exemplar, options, cacheDir), fresh);
}

TEST(AnalysisCache, KeyCoversPixelsAndEveryOption) {
  Image exemplar = test::makeTestPattern(24, 24);
  AnalysisOptions options = smallOptions();
  const std::uint64_t base = analysisCacheKey(exemplar, options);
  EXPECT_EQ(analysisCacheKey(exemplar, options), base);
  Image changed = exemplar;
  changed.pixels[100] += 1e-3f;
  EXPECT_NE(analysisCacheKey(changed, options), base);
  auto differs = [&](auto mutate) {
    AnalysisOptions copy = options;
    mutate(copy);
    return analysisCacheKey(exemplar, copy) != base;
  };
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.levelCount = 2; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.neighborhoodSize = 7; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.levelNeighborhoodSizes = {3, 5}; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.pcaDimensions = 8; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.similarCount = 4; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.exclusionRadius = 3; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.search.backend = AnnBackend::FaissHnsw; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.search.hnswEfSearch = 99; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.featureWeight = 0.25f; }));
  EXPECT_TRUE(differs([](AnalysisOptions& o) { o.featureMask.pixels[3] = 1.0f - o.featureMask.pixels[3]; }));
}

TEST(AnalysisCache, CorruptTruncatedOrForeignFilesAreRecomputed) {
  test::TempDir dir;
  Image exemplar = test::makeTestPattern(24, 24, 3);
  AnalysisOptions options = smallOptions();
  ExemplarAnalysis fresh = analyzeExemplarCached(exemplar, options, dir.path());
  const std::uint64_t key = analysisCacheKey(exemplar, options);
  const std::string path = analysisCachePath(dir.path(), key);
  const std::string good = readFileBytes(path);

  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 0x40;  // one bit deep inside the payload
  std::string wrongVersion = good;
  wrongVersion[8] ^= 0x01;  // the format version follows the 8-byte magic
  const std::vector<std::string> damaged = {flipped,      good.substr(0, good.size() - 5), good.substr(0, 10),
                                            wrongVersion, std::string("not a cache file"), std::string()};
  for (std::size_t i = 0; i < damaged.size(); ++i) {
    SCOPED_TRACE("damage #" + std::to_string(i));
    test::writeBytes(path, damaged[i]);
    EXPECT_FALSE(loadCachedAnalysis(path, key).has_value());
    test::expectIdenticalAnalyses(analyzeExemplarCached(exemplar, options, dir.path()), fresh);
    EXPECT_EQ(readFileBytes(path), good);  // rewritten
  }
  // A valid file stored under another key is not trusted either.
  EXPECT_FALSE(deserializeAnalysis(good, key + 1).has_value());
  EXPECT_TRUE(deserializeAnalysis(good, key).has_value());
}

TEST(AnalysisCache, BadParametersAndUnwritableDirectory) {
  test::TempDir dir;
  Image exemplar = test::makeTestPattern(16, 16);
  AnalysisOptions even;
  even.neighborhoodSize = 6;
  EXPECT_THROW(analyzeExemplarCached(exemplar, even, dir.path()), ParameterError);
  test::writeBytes(dir.file("plain-file"), "x");
  EXPECT_THROW(analyzeExemplarCached(exemplar, {}, dir.file("plain-file")), OutputError);
}
