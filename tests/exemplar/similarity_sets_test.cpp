#include "texsynth/exemplar/similarity_sets.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/exemplar/pca.h"

using namespace texsynth;

namespace {

// Projected 5x5 neighborhoods of a small test pattern: realistic vectors for the search.
struct SmallExemplarVectors {
  int width, height, dimension;
  std::vector<float> data;
  SmallExemplarVectors(int w, int h, int d) : width(w), height(h) {
    Image image = test::makeTestPattern(w, h, 11);
    NeighborhoodShape shape{5, 1, 3};
    PcaBasis pca = fitNeighborhoodPca(image, shape, d);
    dimension = pca.outputDimension;
    data = projectAllNeighborhoods(image, shape, pca);
  }
  PixelVectors view() const { return {data.data(), width, height, dimension}; }
};

float distance(const PixelVectors& v, int a, int b) {
  float sum = 0;
  for (int i = 0; i < v.dimension; ++i) {
    float d = v.at(a)[i] - v.at(b)[i];
    sum += d * d;
  }
  return sum;
}

int ringDistance(int a, int b, int n) {
  int d = std::abs(a - b);
  return std::min(d, n - d);
}

}  // namespace

TEST(SimilaritySets, BruteForceSetsAreSelfFirstSortedAndOutsideTheWindow) {
  SmallExemplarVectors vectors(24, 20, 10);
  SimilarityOptions options;
  options.count = 6;
  options.exclusionRadius = 2;
  options.backend = AnnBackend::BruteForce;
  PixelVectors view = vectors.view();
  std::vector<std::int32_t> sets = computeSimilaritySets(view, options);
  ASSERT_EQ(sets.size(), std::size_t(24 * 20 * 6));
  for (int p = 0; p < 24 * 20; ++p) {
    const std::int32_t* row = &sets[p * 6];
    EXPECT_EQ(row[0], p);
    std::set<int> distinct(row, row + 6);
    EXPECT_EQ(distinct.size(), 6u);
    for (int i = 1; i < 6; ++i) {
      bool near = ringDistance(row[i] % 24, p % 24, 24) <= 2 && ringDistance(row[i] / 24, p / 24, 20) <= 2;
      EXPECT_FALSE(near) << "pixel " << p << " entry " << i;
      if (i > 1) {
        EXPECT_LE(distance(view, p, row[i - 1]), distance(view, p, row[i]));
      }
    }
  }
  // The best entry really is the nearest pixel outside the window.
  for (int p : {0, 100, 479}) {
    float best = 1e30f;
    for (int q = 0; q < 24 * 20; ++q) {
      bool near = ringDistance(q % 24, p % 24, 24) <= 2 && ringDistance(q / 24, p / 24, 20) <= 2;
      if (!near) best = std::min(best, distance(view, p, q));
    }
    EXPECT_EQ(distance(view, p, sets[p * 6 + 1]), best);
  }
}

TEST(SimilaritySets, LibraryBackendsAgreeWithBruteForce) {
  SmallExemplarVectors vectors(32, 32, 12);
  SimilarityOptions options;
  options.count = 5;
  options.exclusionRadius = 2;
  options.backend = AnnBackend::BruteForce;
  std::vector<std::int32_t> exact = computeSimilaritySets(vectors.view(), options);
  options.nanoflannEpsilon = 0.0f;  // exact KD-tree search
  for (AnnBackend backend : {AnnBackend::Nanoflann, AnnBackend::FaissFlat}) {
    options.backend = backend;
    SCOPED_TRACE(annBackendName(backend));
    EXPECT_EQ(computeSimilaritySets(vectors.view(), options), exact);
  }
  // The approximate settings: the default eps-approximate KD-tree and HNSW.
  options.nanoflannEpsilon = SimilarityOptions().nanoflannEpsilon;
  for (AnnBackend backend : {AnnBackend::Nanoflann, AnnBackend::FaissHnsw}) {
    options.backend = backend;
    SCOPED_TRACE(annBackendName(backend));
    std::vector<std::int32_t> found = computeSimilaritySets(vectors.view(), options);
    EXPECT_GE(similarityRecall(found, exact, options.count), 0.95);
  }
}

TEST(SimilaritySets, QuerySubsetMatchesFullRun) {
  SmallExemplarVectors vectors(20, 20, 8);
  SimilarityOptions options;
  options.count = 3;
  std::vector<std::int32_t> all = computeSimilaritySets(vectors.view(), options);
  std::vector<std::int32_t> queries = {399, 0, 57};
  std::vector<std::int32_t> some = computeSimilaritySets(vectors.view(), queries, options);
  for (std::size_t q = 0; q < queries.size(); ++q)
    for (int i = 0; i < 3; ++i) EXPECT_EQ(some[q * 3 + i], all[queries[q] * 3 + i]);
}

TEST(SimilaritySets, CountOneIsThePixelItself) {
  SmallExemplarVectors vectors(8, 8, 4);
  SimilarityOptions options;
  options.count = 1;
  std::vector<std::int32_t> sets = computeSimilaritySets(vectors.view(), options);
  for (int p = 0; p < 64; ++p) EXPECT_EQ(sets[p], p);
}

TEST(SimilaritySets, RecallCountsMissingEntries) {
  std::vector<std::int32_t> exact = {0, 5, 6, 1, 7, 8};
  std::vector<std::int32_t> found = {0, 6, 9, 1, 8, 7};
  EXPECT_DOUBLE_EQ(similarityRecall(found, exact, 3), 0.75);
}

TEST(SimilaritySets, RejectsBadParameters) {
  SmallExemplarVectors vectors(8, 8, 4);
  SimilarityOptions options;
  options.count = 0;
  EXPECT_THROW(computeSimilaritySets(vectors.view(), options), ParameterError);
  options.count = 2;
  options.exclusionRadius = -1;
  EXPECT_THROW(computeSimilaritySets(vectors.view(), options), ParameterError);
  options.exclusionRadius = 4;  // a 9x9 window covers the whole 8x8 torus
  EXPECT_THROW(computeSimilaritySets(vectors.view(), options), ParameterError);
  options.exclusionRadius = 1;
  std::vector<std::int32_t> badQuery = {64};
  EXPECT_THROW(computeSimilaritySets(vectors.view(), badQuery, options), ParameterError);
}

TEST(SimilaritySets, BackendNamesRoundTrip) {
  for (AnnBackend b : {AnnBackend::Nanoflann, AnnBackend::FaissFlat, AnnBackend::FaissHnsw, AnnBackend::BruteForce})
    EXPECT_EQ(parseAnnBackend(annBackendName(b)), b);
  EXPECT_THROW(parseAnnBackend("kd-forest"), ParameterError);
}
