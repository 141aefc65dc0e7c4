// Seam feathering: a coherent copy keeps its exact colors, the pixels beside a seam take the
// Gaussian mean of the pieces their neighbors continue, pixels farther than the radius keep
// theirs; a pixel depends only on the coordinates around it; the same bits for any thread count.
#include "texsynth/image/seam_blend.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"

namespace texsynth {
namespace {

constexpr int kSide = 32;

// kSide^2 coordinates whose left half copies the exemplar from (ax, ay) and right half from
// (bx, by), wrapping: one seam, between columns 15 and 16.
SourceCoordinates twoPieces(const Image& exemplar, int ax, int ay, int bx, int by) {
  SourceCoordinates coords(0, 0, kSide, kSide);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const bool left = x < kSide / 2;
      coords.at(x, y)[0] = wrapIndex(x + (left ? ax : bx), exemplar.width);
      coords.at(x, y)[1] = wrapIndex(y + (left ? ay : by), exemplar.height);
    }
  return coords;
}

TEST(SeamBlend, ACoherentCopyKeepsItsColors) {
  const Image exemplar = test::makeTestPattern(48, 40);
  const SourceCoordinates copy = twoPieces(exemplar, 25, 17, 25, 17);
  EXPECT_EQ(seamBlendedColors(exemplar, copy, 0, 1.5f).pixels, lookupColors(exemplar, copy).pixels);
  EXPECT_EQ(seamBlendedColors(exemplar, copy, 0, 0.0f).pixels, lookupColors(exemplar, copy).pixels);
}

TEST(SeamBlend, FeathersOnlyWithinTheRadiusOfASeam) {
  const Image exemplar = test::makeTestPattern(48, 40);
  const SourceCoordinates coords = twoPieces(exemplar, 3, 4, 20, 25);
  const float sigma = 0.6f;  // radius round(0.9) = 1
  const Image blended = seamBlendedColors(exemplar, coords, 3, sigma);
  const Image crisp = lookupColors(exemplar, coords, 3);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const float* got = blended.pixel(x, y);
      if (x != kSide / 2 - 1 && x != kSide / 2) {
        for (int c = 0; c < 3; ++c) ASSERT_EQ(got[c], crisp.pixel(x, y)[c]) << x << "," << y;
        continue;
      }
      // The Gaussian mean over the 3x3 window (inside the output) of what each neighbor's
      // piece continues to here.
      float expected[3] = {0, 0, 0}, total = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (y + dy < 0 || y + dy >= kSide) continue;
          const std::int32_t* q = coords.at(x + dx, y + dy);
          const float* color =
              exemplar.pixel(wrapIndex(q[0] - dx, exemplar.width), wrapIndex(q[1] - dy, exemplar.height));
          const float weight = std::exp(-float(dx * dx + dy * dy) / (2 * sigma * sigma));
          for (int c = 0; c < 3; ++c) expected[c] += weight * color[c];
          total += weight;
        }
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(got[c], expected[c] / total, 1e-5f) << x << "," << y;
    }
  EXPECT_NE(blended.pixels, crisp.pixels);  // the two pieces differ: the seam did change
}

TEST(SeamBlend, APixelDependsOnlyOnTheCoordinatesAroundIt) {
  const Image exemplar = test::makeTestPattern(48, 40);
  const SourceCoordinates coords = twoPieces(exemplar, 7, 1, 33, 12);
  const float sigma = 1.5f;  // radius 2
  const Image whole = seamBlendedColors(exemplar, coords, 0, sigma);
  // A 20x12 window from (6, 9): its pixels 2 or more inside its border see the same neighbors.
  SourceCoordinates window(0, 0, 20, 12);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 20; ++x) std::copy_n(coords.at(6 + x, 9 + y), 2, window.at(x, y));
  const Image part = seamBlendedColors(exemplar, window, 0, sigma);
  for (int y = 2; y < 10; ++y)
    for (int x = 2; x < 18; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(part.pixel(x, y)[c], whole.pixel(6 + x, 9 + y)[c]) << x << "," << y;
}

TEST(SeamBlend, DoesNotDependOnTheThreadCount) {
  const Image exemplar = test::makeTestPattern(48, 40);
  const SourceCoordinates coords = twoPieces(exemplar, 1, 2, 30, 11);
  Image serial;
  {
    ThreadLimit limit(1);
    serial = seamBlendedColors(exemplar, coords, 0, 2.0f);
  }
  EXPECT_EQ(seamBlendedColors(exemplar, coords, 0, 2.0f).pixels, serial.pixels);
}

TEST(SeamBlend, RejectsABadWidth) {
  const Image exemplar = test::makeTestPattern(16, 16);
  const SourceCoordinates coords(0, 0, 8, 8);
  test::expectParameterError([&] { seamBlendedColors(exemplar, coords, 0, -1.0f); }, "seamBlend");
  test::expectParameterError([&] { seamBlendedColors(exemplar, coords, 0, std::nanf("")); }, "seamBlend");
  test::expectParameterError([&] { seamBlendedColors(exemplar, coords, 0, 5.0f); }, "seamBlend");
}

}  // namespace
}  // namespace texsynth
