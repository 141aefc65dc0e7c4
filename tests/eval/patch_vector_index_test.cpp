// PatchVectorIndex: exact nearest neighbours among given vectors against brute force, limits,
// ties, thread count and bad input.
#include "texsynth/eval/patch_vector_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "eval_test_images.h"
#include "test_support.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

using test::makeTestPattern;
using test::noise;
using test::scaled;

// The raw vectors of every patch of `image`, in PatchIndex's layout.
std::vector<float> patchVectors(const Image& image, int size) {
  std::vector<float> out;
  for (int y = 0; y + size <= image.height; ++y)
    for (int x = 0; x + size <= image.width; ++x)
      for (int dy = 0; dy < size; ++dy)
        out.insert(out.end(), image.pixel(x, y + dy), image.pixel(x, y + dy) + std::size_t(size) * image.channels);
  return out;
}

double meanSquared(const float* a, const float* b, int dims) {
  double sum = 0;
  for (int k = 0; k < dims; ++k) sum += (double(a[k]) - double(b[k])) * (double(a[k]) - double(b[k]));
  return sum / dims;
}

TEST(PatchVectorIndex, NearestMatchesBruteForce) {
  const int size = 5;
  const Image basis = scaled(makeTestPattern(48, 48, 3), 255);
  // Indexed: patches of another texture plus noise patches; queries: patches of the basis image.
  std::vector<float> vectors = patchVectors(scaled(makeTestPattern(30, 26, 7), 255), size);
  const std::vector<float> far = patchVectors(scaled(noise(12, 12, 4), 255), size);
  vectors.insert(vectors.end(), far.begin(), far.end());
  const std::vector<float> queries = patchVectors(basis.crop(3, 5, 30, 30), size);
  PatchVectorIndex index(basis, size);
  const int dims = index.dimensions();
  ASSERT_EQ(dims, size * size * 3);
  index.assign(vectors, vectors.size() / dims);
  const std::size_t count = queries.size() / dims;
  const std::vector<PatchMatch> matches = index.nearestVectors(queries, count);
  ASSERT_EQ(matches.size(), count);
  for (std::size_t i = 0; i < count; ++i) {
    double expected = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < index.size(); ++j)
      expected = std::min(expected, meanSquared(&queries[i * dims], &vectors[j * dims], dims));
    EXPECT_NEAR(matches[i].meanSquared, expected, 1e-6 * std::max(1.0, expected)) << "query " << i;
    EXPECT_DOUBLE_EQ(matches[i].meanSquared,
                     meanSquared(&queries[i * dims], &vectors[std::size_t(matches[i].index) * dims], dims));
  }
  // Limits: only matches within them, the rest -1 and infinity.
  std::vector<double> limits(count);
  for (std::size_t i = 0; i < count; ++i) limits[i] = i % 2 ? matches[i].meanSquared * 2 : matches[i].meanSquared / 2;
  const std::vector<PatchMatch> limited = index.nearestVectors(queries, count, limits);
  for (std::size_t i = 0; i < count; ++i) {
    if (i % 2) {
      EXPECT_EQ(limited[i].meanSquared, matches[i].meanSquared) << "query " << i;
    } else if (matches[i].meanSquared > 0) {
      EXPECT_EQ(limited[i].index, -1) << "query " << i;
      EXPECT_EQ(limited[i].meanSquared, std::numeric_limits<double>::infinity());
    }
  }
}

TEST(PatchVectorIndex, TiesGoToTheLowestIndexAndAssignReplaces) {
  const Image basis = scaled(makeTestPattern(20, 20, 1), 255);
  PatchVectorIndex index(basis, 3);
  const int dims = index.dimensions();
  index.assign(std::vector<float>(std::size_t(dims) * 40, 100.0f), 40);
  for (const PatchMatch& match : index.nearestVectors(std::vector<float>(std::size_t(dims) * 70, 90.0f), 70)) {
    EXPECT_EQ(match.index, 0);
    EXPECT_DOUBLE_EQ(match.meanSquared, 100.0);
  }
  index.assign(std::vector<float>(std::size_t(dims) * 3, 91.0f), 3);
  EXPECT_EQ(index.size(), 3u);
  EXPECT_DOUBLE_EQ(index.nearestVectors(std::vector<float>(std::size_t(dims), 90.0f), 1)[0].meanSquared, 1.0);
}

TEST(PatchVectorIndex, SameResultForAnyThreadCount) {
  const Image basis = scaled(makeTestPattern(40, 40, 2), 255);
  const std::vector<float> vectors = patchVectors(scaled(makeTestPattern(50, 40, 5), 255), 7);
  const std::vector<float> queries = patchVectors(basis, 7);
  std::vector<PatchMatch> one, two;
  for (int threads : {1, 2}) {
    ThreadLimit limit(threads);
    PatchVectorIndex index(basis, 7);
    index.assign(vectors, vectors.size() / index.dimensions());
    (threads == 1 ? one : two) = index.nearestVectors(queries, queries.size() / index.dimensions());
  }
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].index, two[i].index);
    EXPECT_EQ(one[i].meanSquared, two[i].meanSquared);
  }
}

TEST(PatchVectorIndex, RejectsBadInput) {
  const Image basis = scaled(makeTestPattern(20, 20, 1), 255);
  test::expectParameterError([&] { PatchVectorIndex(basis, 0); }, "patchSize");
  test::expectParameterError([&] { PatchVectorIndex(basis, 21); }, "image");
  PatchVectorIndex index(basis, 3);
  const std::vector<float> one(std::size_t(index.dimensions()), 1.0f);
  test::expectParameterError([&] { index.nearestVectors(one, 1); }, "queries");  // nothing indexed yet
  test::expectParameterError([&] { index.assign({}, 0); }, "vectors");
  test::expectParameterError([&] { index.assign(one, 2); }, "vectors");
  std::vector<float> nan = one;
  nan[4] = std::numeric_limits<float>::quiet_NaN();
  test::expectParameterError([&] { index.assign(nan, 1); }, "vectors");
  index.assign(one, 1);
  test::expectParameterError([&] { index.nearestVectors(nan, 1); }, "queries");
  test::expectParameterError([&] { index.nearestVectors(one, 2); }, "queries");
  const std::vector<double> negative = {-1.0};
  test::expectParameterError([&] { index.nearestVectors(one, 1, negative); }, "limits");
  const std::vector<double> two = {1.0, 1.0};
  test::expectParameterError([&] { index.nearestVectors(one, 1, two); }, "limits");
}

}  // namespace
}  // namespace texsynth
