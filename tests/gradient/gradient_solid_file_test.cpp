// The .tsgs file: round trips, quantization (exactness, idempotence, error) and its size.
#include "texsynth/gradient/gradient_solid_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "gradient_solid_file_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/volume.h"

namespace texsynth {
namespace {

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  // Empty vectors may hold null data(), which memcmp must not see even with size 0.
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

void expectSameBits(const GradientSolid& a, const GradientSolid& b) {
  EXPECT_EQ(a.voxels, b.voxels);
  EXPECT_EQ(a.controls, b.controls);
  EXPECT_EQ(a.spacing, b.spacing);
  EXPECT_EQ(a.channels, b.channels);
  EXPECT_TRUE(sameBits(a.positive, b.positive));
  EXPECT_TRUE(sameBits(a.distance, b.distance));
  EXPECT_EQ(a.negativeIndex, b.negativeIndex);
  EXPECT_TRUE(sameBits(a.negative, b.negative));
  EXPECT_TRUE(sameBits(a.detail, b.detail));
}

GradientSolid quantized(GradientSolid solid) {
  quantizeGradientSolid(solid);
  return solid;
}

struct Kind {
  bool regions, detail;
};

class GradientSolidFileKinds : public ::testing::TestWithParam<Kind> {};

TEST_P(GradientSolidFileKinds, DecodeGivesExactlyTheQuantizedSolid) {
  const GradientSolid solid = test::randomGradientSolid({13, 9, 17}, 3, GetParam().regions, GetParam().detail);
  const std::string bytes = encodeGradientSolid(solid);
  EXPECT_EQ(bytes.size(), gradientSolidFileBytes(solid));
  const GradientSolid decoded = decodeGradientSolid(bytes, "memory");
  EXPECT_EQ(decoded.hasRegions(), GetParam().regions);
  EXPECT_EQ(decoded.hasDetail(), GetParam().detail);
  expectSameBits(decoded, quantized(solid));
}

TEST_P(GradientSolidFileKinds, QuantizingIsIdempotentAndEncodesTheSame) {
  const GradientSolid solid = test::randomGradientSolid({10, 21, 6}, 2, GetParam().regions, GetParam().detail, 3);
  const GradientSolid once = quantized(solid);
  expectSameBits(quantized(once), once);
  EXPECT_EQ(encodeGradientSolid(once), encodeGradientSolid(solid));
}

TEST_P(GradientSolidFileKinds, FileRoundTripLooksLikeTheOriginal) {
  const GradientSolid solid = test::randomGradientSolid({12, 12, 12}, 3, GetParam().regions, GetParam().detail, 5);
  test::TempDir dir;
  const std::string path = dir.file("solid.tsgs");
  writeGradientSolid(path, solid);
  const GradientSolid read = readGradientSolid(path);
  expectSameBits(read, quantized(solid));
  // The interpolated raster barely moves (0..255 scale), boundaries and grain included.
  GradientEvaluateOptions options;
  options.detail = true;
  EXPECT_LT(gradientSolidRms(read, rasterizeGradientSolid(solid, options), options), 1.5);
}

INSTANTIATE_TEST_SUITE_P(Arrays, GradientSolidFileKinds,
                         ::testing::Values(Kind{false, false}, Kind{true, false}, Kind{false, true}, Kind{true, true}),
                         [](const auto& info) {
                           return std::string(info.param.regions ? "Regions" : "NoRegions") +
                                  (info.param.detail ? "Detail" : "NoDetail");
                         });

// Per channel: values within half an 8-bit step; zero slopes exactly zero; other slopes within half
// a step of the square-root companding, finest near zero.
TEST(GradientSolidFile, QuantizationErrorIsBounded) {
  const GradientSolid solid = test::randomGradientSolid({20, 20, 20}, 3, false, false);
  const GradientSolid q = quantized(solid);
  const int channels = solid.channels, setSize = solid.setSize();
  for (int c = 0; c < channels; ++c) {
    float lo = INFINITY, hi = -INFINITY, g = 0;
    for (std::size_t i = 0; i < solid.positive.size(); i += std::size_t(setSize)) {
      lo = std::min(lo, solid.positive[i + c]), hi = std::max(hi, solid.positive[i + c]);
      for (int slot = 1; slot < 4; ++slot) g = std::max(g, std::abs(solid.positive[i + slot * channels + c]));
    }
    for (std::size_t i = 0; i < solid.positive.size(); i += std::size_t(setSize)) {
      EXPECT_LE(std::abs(q.positive[i + c] - solid.positive[i + c]), (hi - lo) / 510 * 1.0001f);
      for (int slot = 1; slot < 4; ++slot) {
        const float x = solid.positive[i + slot * channels + c], y = q.positive[i + slot * channels + c];
        if (x == 0.0f) {
          EXPECT_EQ(y, 0.0f);
        }
        const float s = std::sqrt(std::abs(x) / g);
        EXPECT_LE(std::abs(y - x), g * (s / 127 + 1.0f / (254 * 254)) * 1.001f + 1e-7f) << x;
      }
    }
  }
}

TEST(GradientSolidFile, NegativeSetsAreStoredInControlOrder) {
  GradientSolid solid = test::randomGradientSolid({9, 9, 9}, 1, true, false);
  // Two boundary control points sharing one set get one set each in the file.
  std::int32_t shared = -1;
  for (std::int32_t& index : solid.negativeIndex) {
    if (index < 0) continue;
    if (shared < 0) shared = index;
    index = shared;
  }
  const GradientSolid decoded = decodeGradientSolid(encodeGradientSolid(solid), "memory");
  std::int32_t next = 0;
  for (std::size_t i = 0; i < decoded.negativeIndex.size(); ++i)
    if (solid.negativeIndex[i] >= 0) {
      EXPECT_EQ(decoded.negativeIndex[i], next);
      ++next;
    }
  EXPECT_EQ(decoded.negative.size(), std::size_t(next) * std::size_t(decoded.setSize()));
  expectSameBits(decoded, quantized(solid));
}

TEST(GradientSolidFile, DetailSigmaIsNeverNegative) {
  const GradientSolid q = quantized(test::randomGradientSolid({8, 8, 8}, 2, false, true));
  const int setSize = q.setSize();
  for (std::size_t i = 0; i < q.detail.size(); ++i)
    if (int(i % std::size_t(setSize)) < q.channels) {
      EXPECT_GE(q.detail[i], 0.0f);
    }
}

TEST(GradientSolidFile, NonFiniteValuesAreRefusedWhenWriting) {
  GradientSolid solid = test::randomGradientSolid({5, 5, 5}, 1, false, false);
  solid.positive[7] = NAN;
  test::expectParameterError([&] { encodeGradientSolid(solid); }, "solid");
  test::expectParameterError([&] { quantizeGradientSolid(solid); }, "solid");
}

// §5.2: 8-bit control points cost 6.5% of an 8-bit raster without regions. At 128^3 and spacing 4
// there are 33^3 control points of 4 slots x 3 channels: 6.86% with the header and ranges.
TEST(GradientSolidFile, FileIsAboutSixPointNinePercentOfTheRawVolume) {
  const GradientSolid solid = GradientSolid::zeros({128, 128, 128}, 3);
  EXPECT_EQ(rawVolumeBytes(solid), 128u * 128u * 128u * 3u);
  EXPECT_EQ(gradientSolidFileBytes(solid), encodeGradientSolid(solid).size());
  const double ratio = double(gradientSolidFileBytes(solid)) / double(rawVolumeBytes(solid));
  EXPECT_GT(ratio, 0.0685);
  EXPECT_LT(ratio, 0.07);
}

TEST(GradientSolidFile, MissingFileNamesThePath) {
  test::TempDir dir;
  const std::string path = dir.file("absent.tsgs");
  test::expectInputError([&] { readGradientSolid(path); }, path, "does not exist");
}

TEST(GradientSolidFile, FailedWritesLeaveNoFile) {
  test::TempDir dir;
  GradientSolid bad = test::randomGradientSolid({5, 5, 5}, 1, false, false);
  bad.positive[0] = INFINITY;
  EXPECT_THROW(writeGradientSolid(dir.file("bad.tsgs"), bad), ParameterError);
  EXPECT_THROW(writeGradientSolid(dir.file("missing/solid.tsgs"), GradientSolid::zeros({5, 5, 5}, 1)), OutputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace texsynth
