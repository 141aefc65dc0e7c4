// Lattice: tilings and shifted copies score high; noise, photographs, ramps and flat images low.
#include "texsynth/eval/lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "eval_test_images.h"
#include "test_support.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/eval/periodicity.h"
#include "texsynth/io/image_io.h"

namespace texsynth {
namespace {

using test::scaled;

// A GIMP pattern as RGB on 0..255, or nothing when gimp-data is not installed.
std::optional<Image> gimpRgb255(const std::string& name) {
  auto path = gimpPattern(name);
  if (!path) return std::nullopt;
  return scaled(readImage(*path).withChannels(3), 255);
}

// `image` with a copy of its left `width` columns pasted at (x0, y0), clipped to the image.
Image withCopy(Image image, int width, int x0, int y0) {
  const Image source = image;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < width; ++x) {
      const int tx = x + x0, ty = y + y0;
      if (tx < 0 || ty < 0 || tx >= image.width || ty >= image.height) continue;
      for (int c = 0; c < image.channels; ++c) image.at(tx, ty, c) = source.at(x, y, c);
    }
  return image;
}

TEST(Lattice, TiledExemplarScoresNearOne) {
  // Synthetic content: a 64x64 tile repeated 4x4.
  const Image tile = scaled(test::noise(64, 64, 11), 255);
  const LatticePeak synthetic = latticePeak(tile.tiled(256, 256));
  EXPECT_GT(synthetic.strength, 0.9);
  EXPECT_EQ(std::abs(synthetic.dx) % 64, 0);
  EXPECT_EQ(std::abs(synthetic.dy) % 64, 0);
  EXPECT_TRUE(synthetic.dy > 0 || (synthetic.dy == 0 && synthetic.dx > 0));

  // Real content: GIMP's rock (127x80) and stone33 (156x156) tiled 2x2, so that the period lies
  // within the offsets that count (half the image's side).
  for (const char* name : {"Stone/rock.pat", "Stone/stone33.pat"}) {
    SCOPED_TRACE(name);
    auto exemplar = gimpRgb255(name);
    TS_REQUIRE_DATA(exemplar);
    const LatticePeak tiled = latticePeak(exemplar->tiled(2 * exemplar->width, 2 * exemplar->height));
    EXPECT_GT(tiled.strength, 0.8);
    EXPECT_EQ(std::abs(tiled.dx) % exemplar->width, 0);
    EXPECT_EQ(std::abs(tiled.dy) % exemplar->height, 0);
    // The exemplar alone is a photograph with no repeat.
    EXPECT_LT(latticeStrength(*exemplar), 0.3);
  }
}

TEST(Lattice, NoiseScoresLow) {
  EXPECT_LT(latticeStrength(scaled(test::noise(256, 256, 3), 255)), 0.2);
  EXPECT_LT(latticeStrength(scaled(test::noise(97, 61, 4), 255)), 0.2);  // odd sizes, other padding
}

TEST(Lattice, ShiftedRepeatScoresHigh) {
  // The right half copies the left half: one repeat at (100, 0).
  const Image base = scaled(test::noise(200, 128, 5), 255);
  const LatticePeak half = latticePeak(withCopy(base, 100, 100, 0));
  EXPECT_GT(half.strength, 0.9);
  EXPECT_EQ(half.dx, 100);
  EXPECT_EQ(half.dy, 0);

  // Shifted down by 5 too, and every copied value off by up to +-12: no exact duplicate patch is
  // left, so periodicity misses the repeat, but lattice still finds it at (100, 5).
  Image noisy = withCopy(base, 100, 100, 5);
  for (int y = 0; y < noisy.height; ++y)
    for (int x = 100; x < 200; ++x)
      for (int c = 0; c < 3; ++c) noisy.at(x, y, c) += float(24 * uniform01(hashKey(99, (y * 200 + x) * 3 + c)) - 12);
  const LatticePeak shifted = latticePeak(noisy);
  EXPECT_GT(shifted.strength, 0.5);
  EXPECT_EQ(shifted.dx, 100);
  EXPECT_EQ(shifted.dy, 5);
  EXPECT_LT(periodicity(PatchIndex(noisy, 7), {500, 4.0, 1}), 0.05);
}

TEST(Lattice, SmoothAndFlatImagesScoreLow) {
  EXPECT_EQ(latticeStrength(Image(64, 48, 3, 128.0f)), 0.0);  // zero variance
  EXPECT_EQ(latticePeak(Image(64, 48, 3, 128.0f)).dx, 0);
  const int w = 256, h = 192;
  Image horizontal(w, h, 3), vertical(w, h, 3), diagonal(w, h, 3), radial(w, h, 3), waves(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        horizontal.at(x, y, c) = 255.0f * x / (w - 1);
        vertical.at(x, y, c) = 255.0f * y / (h - 1);
        diagonal.at(x, y, c) = 0.5f * (x + y) + 20 * c;
        radial.at(x, y, c) = 255.0f * float(std::hypot(x - 90.0, y - 70.0) / 300);
        waves.at(x, y, c) = 128 + 60 * std::sin(0.01f * x) * std::cos(0.013f * y);  // slow shading
      }
  for (const Image* image : {&horizontal, &vertical, &diagonal, &radial, &waves}) {
    SCOPED_TRACE(image - &horizontal);
    EXPECT_LT(latticeStrength(*image), 0.2);
  }
}

TEST(Lattice, TinyAndEmptyImagesScoreZero) {
  EXPECT_EQ(latticeStrength(Image()), 0.0);
  EXPECT_EQ(latticeStrength(scaled(test::noise(1, 1, 1), 255)), 0.0);
  EXPECT_EQ(latticeStrength(scaled(test::noise(5, 5, 1), 255)), 0.0);  // every offset is within 2 px
  EXPECT_GE(latticeStrength(scaled(test::noise(1, 40, 2), 255)), 0.0);
  EXPECT_GE(latticeStrength(scaled(test::noise(7, 3, 2, 1), 255)), 0.0);  // one channel
}

TEST(Lattice, DeterministicAcrossThreadsAndPartOfTheMetrics) {
  const Image tile = test::makeTestPattern(50, 40, 5);
  Image output = tile.tiled(150, 130);
  for (int i = 0; i < 60; ++i) output.at((i * 37) % 150, (i * 53) % 130, 0) += 0.3f;  // break some repeats
  double one, two;
  QualityMetrics metrics;
  {
    ThreadLimit limit(1);
    one = latticeStrength(scaled(output, 255));
    metrics = evaluateImage(tile, output, {.periodicitySamples = 200});
  }
  {
    ThreadLimit limit(2);
    two = latticeStrength(scaled(output, 255));
  }
  EXPECT_EQ(one, two);
  EXPECT_GT(one, 0.8);
  // evaluateImage scales by 255 the same way.
  EXPECT_EQ(metrics.lattice, one);
  EXPECT_EQ(evaluateImage(tile, tile, {.periodicitySamples = 200}).lattice, latticeStrength(scaled(tile, 255)));
}

TEST(Lattice, RejectsBadOptionsAndValues) {
  const Image image = scaled(test::noise(32, 32, 1), 255);
  EXPECT_THROW(latticeStrength(image, {.highPassSigma = -1}), ParameterError);
  EXPECT_THROW(latticeStrength(image, {.highPassSigma = std::nan("")}), ParameterError);
  EXPECT_THROW(latticeStrength(image, {.lobeThreshold = 1.5}), ParameterError);
  EXPECT_GE(latticeStrength(image, {.highPassSigma = 0}), 0.0);  // no high-pass
  Image bad = image;
  bad.at(3, 4, 1) = std::nanf("");
  EXPECT_THROW(latticeStrength(bad), ParameterError);
}

}  // namespace
}  // namespace texsynth
