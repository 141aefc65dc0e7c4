#include "texsynth/exemplar/candidate_triples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "exemplar_test_util.h"
#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/io/image_io.h"

using namespace texsynth;
namespace fs = std::filesystem;

namespace {

constexpr Plane kPlanes[3] = {Plane::XY, Plane::YZ, Plane::ZX};

CandidateTripleOptions smallOptions() {
  CandidateTripleOptions options;
  options.count = 6;
  options.neighborhoodSize = 5;
  options.searchWidth = 8;
  return options;
}

// Constant along rows: row y has colour palette[(y / thickness) % 4].
Image stripes(int size, int thickness) {
  const float palette[4][3] = {{0.9f, 0.1f, 0.2f}, {0.1f, 0.8f, 0.3f}, {0.2f, 0.3f, 0.9f}, {0.7f, 0.7f, 0.1f}};
  Image image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = palette[(y / thickness) % 4][c];
  return image;
}

void expectIdentical(const CandidateTriples& a, const CandidateTriples& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.count, b.count);
  ASSERT_EQ(a.neighborhoodSize, b.neighborhoodSize);
  for (int p = 0; p < 3; ++p) {
    EXPECT_TRUE(a.triples[p] == b.triples[p]) << "plane " << p;
    EXPECT_TRUE(test::bitwiseEqual(a.errors[p], b.errors[p])) << "plane " << p;
  }
}

std::int32_t anchorOf(const CoordinateTriple& t, Plane plane) {
  return plane == Plane::XY ? t.xy : plane == Plane::YZ ? t.yz : t.zx;
}

}  // namespace

TEST(CandidateTriples, StripesWhosePeriodDividesTheSpacingMatchExactly) {
  // Crossbar samples 4 apart all fall on one colour, so every pixel has error-0 triples.
  Image image = stripes(32, 1);
  CandidateTriples t = computeCandidateTriples(image, image, image, 4, smallOptions());
  for (Plane plane : kPlanes)
    for (std::int32_t p = 0; p < t.pixelCount(); ++p) ASSERT_LE(t.errorsAt(plane, p)[0], 1e-6f);
}

TEST(CandidateTriples, ThickStripesMatchExactlyAwayFromStripeBorders) {
  Image image = stripes(32, 8);
  CandidateTriples t = computeCandidateTriples(image, image, image, 1, smallOptions());
  for (Plane plane : kPlanes)
    for (int y = 2; y < 32; y += 8)  // rows 2..5 of each 8-row stripe hold the whole 5-sample column
      for (int x = 0; x < 32; ++x)
        for (int dy = 0; dy < 4; ++dy) ASSERT_LE(t.errorsAt(plane, (y + dy) * 32 + x)[0], 1e-6f);
  // Noise has no exact triples: the test can fail.
  Image noise = test::makeTestPattern(32, 32, 5);
  CandidateTriples n = computeCandidateTriples(noise, noise, noise, 1, smallOptions());
  double mean = 0;
  for (std::int32_t p = 0; p < n.pixelCount(); ++p) mean += n.errorsAt(Plane::XY, p)[0];
  EXPECT_GT(mean / n.pixelCount(), 0.01);
}

TEST(CandidateTriples, ListsAreAscendingContainTheirAnchorAndStoreTheExactError) {
  Image xy = test::makeTestPattern(24, 20, 1), yz = test::makeTestPattern(24, 20, 2),
        zx = test::makeTestPattern(24, 20, 3);
  CandidateTripleOptions options = smallOptions();
  CandidateTriples t = computeCandidateTriples(xy, yz, zx, 2, options);
  ASSERT_EQ(t.width, 24);
  ASSERT_EQ(t.height, 20);
  ASSERT_EQ(t.count, options.count);
  for (Plane plane : kPlanes)
    for (std::int32_t p = 0; p < t.pixelCount(); ++p) {
      const CoordinateTriple* triples = t.at(plane, p);
      const float* errors = t.errorsAt(plane, p);
      for (int k = 0; k < t.count; ++k) {
        ASSERT_EQ(anchorOf(triples[k], plane), p);
        if (k > 0) {
          ASSERT_LE(errors[k - 1], errors[k]);
        }
        for (int j = 0; j < k; ++j) ASSERT_FALSE(triples[j] == triples[k]) << "duplicate triple";
        if (p % 7 == 0) {
          ASSERT_EQ(errors[k], crossbarError(xy, yz, zx, triples[k], 2, options.neighborhoodSize));
        }
      }
    }
}

TEST(CandidateTriples, BestTriplesBeatRandomTriplesOnARealExemplar) {
  auto path = gimpPattern("Stone/pink_marble.pat");
  TS_REQUIRE_DATA(path);
  Image image = readImage(*path).withChannels(3).crop(0, 0, 64, 64);
  CandidateTriples t = computeCandidateTriples(image, image, image, 1);
  double best = 0, random = 0;
  for (std::int32_t p = 0; p < t.pixelCount(); ++p) {
    best += t.errorsAt(Plane::XY, p)[0];
    CoordinateTriple r{p, std::int32_t(uniformBelow(hashKey(1, p), 4096)),
                       std::int32_t(uniformBelow(hashKey(2, p), 4096))};
    random += crossbarError(image, image, image, r, 1, 9);
  }
  EXPECT_LT(best, 0.5 * random) << "mean best " << best / 4096 << ", mean random " << random / 4096;
}

TEST(CandidateTriples, ConsistencyFilterPrefersConsistentTriples) {
  Image image = test::makeTestPattern(32, 32, 4);
  CandidateTripleOptions options = smallOptions();
  CandidateTriples filtered = computeCandidateTriples(image, image, image, 1, options);
  options.consistencyFactor = std::numeric_limits<float>::infinity();
  CandidateTriples plain = computeCandidateTriples(image, image, image, 1, options);
  // The rule, evaluated independently: a shifted triple about as good as the neighbour's best.
  auto consistent = [&](const CoordinateTriple& t, int plane) {
    for (int e = 0; e < 4; ++e) {
      const int du = e == 0 ? 1 : e == 1 ? -1 : 0, dv = e == 2 ? 1 : e == 3 ? -1 : 0;
      const int d[3][3] = {{du, dv, 0}, {0, du, dv}, {dv, 0, du}};
      CoordinateTriple moved = offsetTriple(t, 32, 32, d[plane][0], d[plane][1], d[plane][2]);
      float neighbourBest = plain.errorsAt(kPlanes[plane], anchorOf(moved, kPlanes[plane]))[0];
      if (crossbarError(image, image, image, moved, 1, 5) <= 2.0f * neighbourBest + 1e-6f) return true;
    }
    return false;
  };
  long consistentFiltered = 0, consistentPlain = 0;
  for (int plane = 0; plane < 3; ++plane)
    for (std::int32_t p = 0; p < 32 * 32; ++p) {
      int a = 0, b = 0;
      for (int k = 0; k < options.count; ++k) {
        a += consistent(filtered.at(kPlanes[plane], p)[k], plane);
        b += consistent(plain.at(kPlanes[plane], p)[k], plane);
      }
      ASSERT_GE(a, b) << "plane " << plane << " pixel " << p;
      consistentFiltered += a;
      consistentPlain += b;
    }
  EXPECT_GT(consistentFiltered, consistentPlain);
}

TEST(CandidateTriples, IndependentOfThreadCount) {
  Image image = test::makeTestPattern(40, 28, 7);
  CandidateTriples one, many;
  {
    ThreadLimit limit(1);
    one = computeCandidateTriples(image, image, image, 2, smallOptions());
  }
  {
    ThreadLimit limit(4);
    many = computeCandidateTriples(image, image, image, 2, smallOptions());
  }
  expectIdentical(one, many);
}

TEST(CandidateTriples, SlabTriplesFollowTheNormalStick) {
  Image image = test::makeTestPattern(24, 24, 9);
  CandidateTripleOptions options = smallOptions();
  CandidateTriples t = computeCandidateTriples(image, image, image, 3, options);
  const int normals[3][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
  for (int plane = 0; plane < 3; ++plane)
    for (std::int32_t p : {0, 77, 575}) {
      const CoordinateTriple first = t.at(kPlanes[plane], p)[0];
      EXPECT_EQ(slabTriple(t, kPlanes[plane], p, 0, 3), first);
      for (int s = -2; s <= 2; ++s) {
        const int* n = normals[plane];
        CoordinateTriple slab = slabTriple(t, kPlanes[plane], p, s, 3);
        EXPECT_EQ(slab, offsetTriple(first, 24, 24, 3 * s * n[0], 3 * s * n[1], 3 * s * n[2]));
        EXPECT_EQ(anchorOf(slab, kPlanes[plane]), p) << "the slab thickens the plane: its own pixel stays";
      }
    }
  test::expectParameterError([&] { slabTriple(t, Plane::XY, 0, 3, 3); }, "t");
  test::expectParameterError([&] { slabTriple(t, Plane::XY, 24 * 24, 0, 3); }, "pixel");
  // Eq. 4 wraps toroidally in every image.
  EXPECT_EQ(offsetTriple({0, 0, 0}, 24, 24, -1, 1, 2), (CoordinateTriple{23 + 24, 1 + 2 * 24, 2 + 23 * 24}));
}

TEST(CandidateTriples, CacheRoundTripKeysAndCorruption) {
  test::TempDir dir;
  Image image = test::makeTestPattern(20, 20, 11);
  CandidateTripleOptions options = smallOptions();
  const std::string cacheDir = dir.file("cache");
  CandidateTriples fresh = computeCandidateTriplesCached(image, image, image, 1, options, cacheDir);
  const std::uint64_t key = candidateTriplesCacheKey(image, image, image, 1, options);
  const std::string path = candidateTriplesCachePath(cacheDir, key);
  ASSERT_TRUE(fs::exists(path));
  expectIdentical(fresh, computeCandidateTriples(image, image, image, 1, options));
  auto loaded = loadCachedCandidateTriples(path, key);
  ASSERT_TRUE(loaded.has_value());
  expectIdentical(*loaded, fresh);
  EXPECT_FALSE(loadCachedCandidateTriples(path, key + 1).has_value());

  auto differs = [&](auto mutate, int spacing = 1) {
    CandidateTripleOptions copy = options;
    mutate(copy);
    return candidateTriplesCacheKey(image, image, image, spacing, copy) != key;
  };
  EXPECT_FALSE(differs([](CandidateTripleOptions&) {}));
  EXPECT_TRUE(differs([](CandidateTripleOptions&) {}, 2));
  EXPECT_TRUE(differs([](CandidateTripleOptions& o) { o.count = 5; }));
  EXPECT_TRUE(differs([](CandidateTripleOptions& o) { o.neighborhoodSize = 7; }));
  EXPECT_TRUE(differs([](CandidateTripleOptions& o) { o.searchWidth = 9; }));
  EXPECT_TRUE(differs([](CandidateTripleOptions& o) { o.consistencyFactor = 3; }));
  EXPECT_TRUE(differs([](CandidateTripleOptions& o) { o.refineTriples = 0; }));
  Image changed = image;
  changed.pixels[50] += 1e-3f;
  EXPECT_NE(candidateTriplesCacheKey(image, changed, image, 1, options), key);
  EXPECT_NE(candidateTriplesCacheKey(image, image, changed, 1, options), key);
  EXPECT_NE(candidateTriplesCacheKey(changed, image, image, 1, options), key);

  const std::string good = readFileBytes(path);
  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 0x40;
  for (const std::string& bad : {flipped, good.substr(0, good.size() - 3), std::string("TSXTRIPL")}) {
    EXPECT_FALSE(deserializeCandidateTriples(bad, key).has_value());
    test::writeBytes(path, bad);
    expectIdentical(computeCandidateTriplesCached(image, image, image, 1, options, cacheDir), fresh);
    EXPECT_EQ(readFileBytes(path), good) << "a bad file is rewritten";
  }
}

TEST(CandidateTriples, BadInputRejected) {
  Image image = test::makeTestPattern(16, 16);
  auto run = [&](const Image& xy, const Image& yz, const Image& zx, int spacing, CandidateTripleOptions options) {
    return [=] { computeCandidateTriples(xy, yz, zx, spacing, options); };
  };
  const CandidateTripleOptions ok = smallOptions();
  test::expectParameterError(run(Image(), image, image, 1, ok), "xy");
  test::expectParameterError(run(image, test::makeTestPattern(16, 15), image, 1, ok), "yz");
  test::expectParameterError(run(image, image, image.withChannels(1), 1, ok), "zx");
  test::expectParameterError(run(image, image, image, 0, ok), "spacing");
  auto with = [&](auto mutate) {
    CandidateTripleOptions o = ok;
    mutate(o);
    return o;
  };
  test::expectParameterError(run(image, image, image, 1, with([](auto& o) { o.count = 0; })), "count");
  test::expectParameterError(run(image, image, image, 1, with([](auto& o) { o.count = 65; })), "count");
  test::expectParameterError(run(image, image, image, 1, with([](auto& o) { o.neighborhoodSize = 4; })),
                             "neighborhoodSize");
  test::expectParameterError(run(image, image, image, 1, with([](auto& o) { o.searchWidth = 0; })), "searchWidth");
  test::expectParameterError(run(image, image, image, 1, with([](auto& o) { o.refineTriples = -1; })), "refineTriples");
  test::expectParameterError(run(image, image, image, 1, with([](auto& o) { o.consistencyFactor = 0.5f; })),
                             "consistencyFactor");
  test::expectParameterError(run(image, image, image, 1, with([](auto& o) { o.consistencyFactor = std::nanf(""); })),
                             "consistencyFactor");
  test::expectParameterError([&] { crossbarError(image, image, image, {0, 0, 256}, 1, 5); }, "triple");
  // A 2x2 exemplar has only 16 pairs per anchor.
  Image tiny = test::makeTestPattern(2, 2);
  test::expectParameterError(run(tiny, tiny, tiny, 1, with([](auto& o) { o.count = 17; })), "count");
  EXPECT_NO_THROW(computeCandidateTriples(tiny, tiny, tiny, 1, with([](auto& o) { o.count = 16; })));
}
