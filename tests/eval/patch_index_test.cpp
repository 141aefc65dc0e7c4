// PatchIndex: exact nearest neighbours and radius search against brute force.
#include "texsynth/eval/patch_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "eval_test_images.h"
#include "test_support.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"

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

// Every patch of `image` as a raw vector (rows top to bottom, channels innermost), row-major.
std::vector<float> patchVectors(const Image& image, int size) {
  std::vector<float> values;
  for (int y = 0; y + size <= image.height; ++y)
    for (int x = 0; x + size <= image.width; ++x)
      for (int dy = 0; dy < size; ++dy)
        values.insert(values.end(), image.pixel(x, y + dy), image.pixel(x, y + dy) + size * image.channels);
  return values;
}

TEST(PatchIndex, NearestVectorsAgreesWithNearestOnImagePatches) {
  // Near queries (a crop of the texture) and far ones (noise), colour and gray.
  Image big = scaled(makeTestPattern(80, 80, 3), 255);
  const Image reference = big.crop(0, 0, 48, 48);
  for (const Image& queries : {big.crop(17, 9, 40, 36), scaled(noise(20, 18, 5), 255)}) {
    PatchIndex index(reference, 7);
    const std::vector<float> values = patchVectors(queries, 7);
    const std::size_t count = values.size() / (7 * 7 * 3);
    std::vector<PatchMatch> expected = index.nearest(queries), found = index.nearestVectors(values, count);
    ASSERT_EQ(found.size(), expected.size());
    // The same distance (the neighbour itself may differ only among ties within float rounding).
    for (std::size_t i = 0; i < found.size(); ++i)
      EXPECT_NEAR(found[i].meanSquared, expected[i].meanSquared, 1e-6 * std::max(1.0, expected[i].meanSquared))
          << "query " << i;
  }
  Image gray = scaled(makeTestPattern(50, 50, 9).withChannels(1), 255);
  PatchIndex grayIndex(gray, 5);
  std::vector<double> brute = bruteForceNearest(gray.crop(3, 4, 20, 20), gray, 5);
  std::vector<PatchMatch> found = grayIndex.nearestVectors(patchVectors(gray.crop(3, 4, 20, 20), 5), brute.size());
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_EQ(found[i].meanSquared, 0.0);
}

TEST(PatchIndex, NearestVectorsMatchesBruteForceOnTransformedPatches) {
  // Mirrored patches of the reference: not patches of any image the index saw.
  Image reference = scaled(makeTestPattern(40, 40, 6), 255);
  const int size = 5, channels = 3;
  std::vector<float> values;
  std::vector<double> expected;
  PatchIndex index(reference, size);
  for (int q = 0; q < 60; ++q) {
    const int x = int(uniformBelow(hashKey(3, q, 0), 36)), y = int(uniformBelow(hashKey(3, q, 1), 36));
    std::vector<float> patch;
    for (int dy = 0; dy < size; ++dy)
      for (int dx = size - 1; dx >= 0; --dx)
        patch.insert(patch.end(), reference.pixel(x + dx, y + dy), reference.pixel(x + dx, y + dy) + channels);
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < int(index.size()); ++i) {
      double sum = 0;
      for (int dy = 0; dy < size; ++dy)
        for (int k = 0; k < size * channels; ++k) {
          double diff = double(patch[dy * size * channels + k]) -
                        double(reference.pixel(i % index.columns(), i / index.columns() + dy)[k]);
          sum += diff * diff;
        }
      best = std::min(best, sum / (size * size * channels));
    }
    expected.push_back(best);
    values.insert(values.end(), patch.begin(), patch.end());
  }
  // Limits: at the nearest distance the nearest is still found; below it, nothing is.
  std::vector<double> atNearest = expected, belowNearest;
  for (double e : expected) belowNearest.push_back(0.9 * e - 0.01);
  std::vector<PatchMatch> bounded = index.nearestVectors(values, expected.size(), atNearest);
  std::vector<PatchMatch> none = index.nearestVectors(values, expected.size(), belowNearest);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(bounded[i].meanSquared, expected[i], 1e-6 * std::max(1.0, expected[i])) << "query " << i;
    EXPECT_EQ(none[i].index, -1) << "query " << i;
    EXPECT_EQ(none[i].meanSquared, std::numeric_limits<double>::infinity());
  }
  std::vector<PatchMatch> one, two;
  {
    ThreadLimit limit(1);
    one = index.nearestVectors(values, expected.size());
  }
  {
    ThreadLimit limit(2);
    two = index.nearestVectors(values, expected.size());
  }
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(one[i].meanSquared, expected[i], 1e-6 * std::max(1.0, expected[i])) << "query " << i;
    EXPECT_EQ(one[i].index, two[i].index);
    EXPECT_EQ(one[i].meanSquared, two[i].meanSquared);
  }
}

TEST(PatchIndex, NearestVectorsRejectsBadInput) {
  PatchIndex index(makeTestPattern(10, 10), 3);
  EXPECT_TRUE(index.nearestVectors({}, 0).empty());
  std::vector<float> values(27 * 2, 0.5f);
  EXPECT_EQ(index.nearestVectors(values, 2).size(), 2u);
  EXPECT_THROW(index.nearestVectors(values, 3), ParameterError);  // too few values
  values.push_back(0);
  EXPECT_THROW(index.nearestVectors(values, 2), ParameterError);  // a partial vector
  values.pop_back();
  EXPECT_THROW(index.nearestVectors(values, 2, std::vector<double>{1.0}), ParameterError);  // one limit
  EXPECT_THROW(index.nearestVectors(values, 2, std::vector<double>{1.0, -1.0}), ParameterError);
  EXPECT_EQ(index.nearestVectors(values, 2, std::vector<double>{0.0, std::numeric_limits<double>::infinity()})[1].index,
            index.nearestVectors(values, 2)[1].index);
  values[5] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(index.nearestVectors(values, 2), ParameterError);
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
