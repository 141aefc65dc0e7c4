// PatchIndex: exact nearest neighbours and radius search against brute force.
#include "texsynth/eval/patch_index.h"

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

// The brute-force nearest distance of every query patch, in double.
std::vector<double> bruteForceNearest(const Image& queries, const Image& reference, int size) {
  std::vector<double> best;
  for (int y = 0; y + size <= queries.height; ++y)
    for (int x = 0; x + size <= queries.width; ++x) {
      double d = std::numeric_limits<double>::infinity();
      for (int ry = 0; ry + size <= reference.height; ++ry)
        for (int rx = 0; rx + size <= reference.width; ++rx)
          d = std::min(d, PatchIndex::meanSquaredDifference(queries, x, y, reference, rx, ry, size));
      best.push_back(d);
    }
  return best;
}

void expectExact(const Image& queries, const Image& reference, int size) {
  PatchIndex index(reference, size);
  std::vector<PatchMatch> matches = index.nearest(queries);
  std::vector<double> expected = bruteForceNearest(queries, reference, size);
  ASSERT_EQ(matches.size(), expected.size());
  for (std::size_t i = 0; i < matches.size(); ++i) {
    // Only ties within float rounding may pick another neighbour than brute force.
    EXPECT_NEAR(matches[i].meanSquared, expected[i], 1e-6 * std::max(1.0, expected[i])) << "query " << i;
    const int x = matches[i].index % index.columns(), y = matches[i].index / index.columns();
    EXPECT_DOUBLE_EQ(matches[i].meanSquared,
                     PatchIndex::meanSquaredDifference(queries, int(i) % (queries.width - size + 1),
                                                       int(i) / (queries.width - size + 1), reference, x, y, size));
  }
}

TEST(PatchIndex, NearestMatchesBruteForceOnTexture) {
  Image big = scaled(makeTestPattern(80, 80, 3), 255);
  expectExact(big.crop(17, 9, 40, 36), big.crop(0, 0, 48, 48), 7);
}

TEST(PatchIndex, NearestMatchesBruteForceForFarQueries) {
  // Noise queries are far from every texture patch: the bounds prune little, results stay exact.
  expectExact(scaled(noise(30, 30, 5), 255), scaled(makeTestPattern(40, 40), 255), 5);
}

TEST(PatchIndex, NearestMatchesBruteForceOnGrayAndLargePatches) {
  Image gray = scaled(makeTestPattern(50, 50, 9).withChannels(1), 255);
  expectExact(gray.crop(5, 5, 30, 30), gray, 9);
}

TEST(PatchIndex, IdenticalPatchesAreFoundAtDistanceZero) {
  Image image = scaled(makeTestPattern(40, 40), 255);
  PatchIndex index(image, 7);
  std::vector<PatchMatch> matches = index.nearest(image);
  for (std::size_t i = 0; i < matches.size(); ++i) {
    EXPECT_EQ(matches[i].meanSquared, 0.0);
    EXPECT_EQ(matches[i].index, int(i));
  }
}

TEST(PatchIndex, TiesGoToTheLowestPatchIndex) {
  Image flat(20, 16, 3, 100.0f);
  PatchIndex index(flat, 5);
  for (const PatchMatch& match : index.nearest(Image(12, 12, 3, 90.0f))) {
    EXPECT_EQ(match.index, 0);
    EXPECT_DOUBLE_EQ(match.meanSquared, 100.0);
  }
}

TEST(PatchIndex, WithinMatchesBruteForce) {
  // Two copies of a 24-wide texture side by side plus noise: duplicates at exactly +-24.
  Image tile = scaled(makeTestPattern(24, 30, 4), 255);
  Image image = tile.tiled(60, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 48; x < 60; ++x) image.at(x, y, 0) += 3.0f * float(x % 3);  // near-duplicates
  PatchIndex index(image, 5);
  for (int y : {0, 7, 25})
    for (int x : {0, 3, 20, 40, 55}) {
      for (double limit : {0.0, 1.0, 4.0, 50.0}) {
        std::vector<int> expected;
        for (int i = 0; i < int(index.size()); ++i)
          if (PatchIndex::meanSquaredDifference(image, x, y, image, i % index.columns(), i / index.columns(), 5) <=
              limit)
            expected.push_back(i);
        EXPECT_EQ(index.within(image, x, y, limit), expected) << x << "," << y << " limit " << limit;
      }
    }
}

TEST(PatchIndex, SameResultForAnyThreadCount) {
  Image reference = scaled(makeTestPattern(64, 64, 2), 255);
  Image queries = scaled(makeTestPattern(90, 70, 8), 255);
  std::vector<PatchMatch> one, two;
  {
    ThreadLimit limit(1);
    one = PatchIndex(reference, 7).nearest(queries);
  }
  {
    ThreadLimit limit(2);
    two = PatchIndex(reference, 7).nearest(queries);
  }
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].index, two[i].index);
    EXPECT_EQ(one[i].meanSquared, two[i].meanSquared);
  }
}

TEST(PatchIndex, RejectsBadInput) {
  Image image = makeTestPattern(10, 10);
  EXPECT_THROW(PatchIndex(image, 0), ParameterError);
  EXPECT_THROW(PatchIndex(image, 11), ParameterError);
  EXPECT_THROW(PatchIndex(Image(), 3), ParameterError);
  PatchIndex index(image, 3);
  EXPECT_THROW(index.nearest(Image(10, 10, 1)), ParameterError);  // channel mismatch
  EXPECT_THROW(index.nearest(Image(2, 10, 3)), ParameterError);   // smaller than a patch
}

}  // namespace
}  // namespace texsynth
