// Malformed .tsgs files: each raises one InputError naming the file, never a crash or a huge
// allocation. Files with a changed header get a fresh CRC so the check under test is reached.
#include <gtest/gtest.h>
#include <zlib.h>

#include <bit>
#include <cmath>

#include "gradient_solid_file_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/gradient/gradient_solid_file.h"

namespace texsynth {
namespace {

const std::string kWhere = "bad.tsgs";

// Header offsets (docs/gradient-solids.md).
constexpr std::size_t kVersion = 8, kVoxels = 12, kSpacing = 24, kChannels = 28, kFlags = 32, kNegatives = 36,
                      kMask = 40;

// A small file with every array: 2 channels, 2 x 3 x 3 control points, some negative sets.
GradientSolid smallSolid() {
  return test::randomGradientSolid({5, 6, 7}, 2, true, true);
}

std::uint32_t u32At(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int b = 0; b < 4; ++b) v |= std::uint32_t(std::uint8_t(bytes[at + b])) << (8 * b);
  return v;
}

void setU32(std::string& bytes, std::size_t at, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) bytes[at + b] = char((v >> (8 * b)) & 0xff);
}

// Rewrites the trailing CRC-32 so that only the change under test is wrong.
std::string withCrc(std::string bytes) {
  const uLong crc = crc32(crc32(0L, nullptr, 0), reinterpret_cast<const Bytef*>(bytes.data()), uInt(bytes.size() - 4));
  setU32(bytes, bytes.size() - 4, std::uint32_t(crc));
  return bytes;
}

std::string changed(std::size_t at, std::uint32_t v) {
  std::string bytes = encodeGradientSolid(smallSolid());
  setU32(bytes, at, v);
  return withCrc(bytes);
}

void expectRejected(const std::string& bytes, const std::string& problem) {
  test::expectInputError([&] { decodeGradientSolid(bytes, kWhere); }, kWhere, problem);
}

// Where the positive sets' parameters start: after the header and the boundary mask.
std::size_t positiveParams(const GradientSolid& solid) {
  return kMask + std::size_t(solid.controlCount() + 7) / 8;
}

TEST(GradientSolidFileMalformed, EveryTruncationIsCaught) {
  const std::string bytes = encodeGradientSolid(smallSolid());
  ASSERT_LT(bytes.size(), 2000u);
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    SCOPED_TRACE(length);
    expectRejected(bytes.substr(0, length), "truncated");
  }
}

TEST(GradientSolidFileMalformed, EveryFlippedByteIsCaught) {
  const std::string bytes = encodeGradientSolid(smallSolid());
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    SCOPED_TRACE(at);
    for (std::uint8_t flip : {0x01, 0x80}) {
      std::string corrupted = bytes;
      corrupted[at] = char(std::uint8_t(corrupted[at]) ^ flip);
      expectRejected(corrupted, "");
    }
  }
  // Past the header, only the checksum can tell.
  std::string corrupted = bytes;
  corrupted[bytes.size() / 2] ^= 0x10;
  expectRejected(corrupted, "CRC-32 mismatch");
}

TEST(GradientSolidFileMalformed, SignatureVersionAndTrailingBytes) {
  const std::string bytes = encodeGradientSolid(smallSolid());
  expectRejected("P3\n2 2\n255\n0 0 0", "signature");
  expectRejected("TSGSOLIX" + bytes.substr(8), "signature");
  expectRejected(changed(kVersion, 2), "unsupported .tsgs version 2");
  expectRejected(bytes + '\0', "1 trailing bytes");
  expectRejected(changed(kFlags, 7), "unknown flags");
}

TEST(GradientSolidFileMalformed, AbsurdSizes) {
  for (std::size_t axis = 0; axis < 3; ++axis) {
    expectRejected(changed(kVoxels + 4 * axis, 0), "voxels 0 is outside [1, 65536]");
    expectRejected(changed(kVoxels + 4 * axis, 65537), "voxels 65537");
    expectRejected(changed(kVoxels + 4 * axis, std::uint32_t(-3)), "voxels -3");
  }
  expectRejected(changed(kSpacing, 0), "spacing 0");
  expectRejected(changed(kSpacing, 65), "spacing 65");
  expectRejected(changed(kChannels, 0), "channels 0");
  expectRejected(changed(kChannels, 5), "channels 5");
}

TEST(GradientSolidFileMalformed, SizesTheFileDoesNotHold) {
  // More control points than the bytes hold (up to 65537^3): refused before any allocation.
  expectRejected(changed(kVoxels, 6000), "truncated");
  std::string huge = changed(kVoxels, 65536);
  setU32(huge, kVoxels + 4, 65536);
  setU32(huge, kVoxels + 8, 65536);
  setU32(huge, kSpacing, 1);
  expectRejected(withCrc(huge), "truncated");
  expectRejected(changed(kChannels, 4), "truncated");
  // Fewer control points than stored.
  expectRejected(changed(kVoxels + 8, 2), "trailing bytes");
}

TEST(GradientSolidFileMalformed, NegativeSetCounts) {
  const GradientSolid solid = smallSolid();
  const std::string bytes = encodeGradientSolid(solid);
  const std::uint32_t negatives = u32At(bytes, kNegatives);
  ASSERT_GT(negatives, 0u);
  expectRejected(changed(kNegatives, 1000), "more negative sets (1000) than control points (18)");
  expectRejected(changed(kNegatives, negatives + 1), "truncated");
  expectRejected(changed(kFlags, 2), "negative sets in a solid without regions");
  // The mask marks one more (or one fewer) control point than the header counts.
  for (std::uint8_t bit = 0; bit < 8; ++bit) {
    std::string lying = bytes;
    lying[kMask] = char(std::uint8_t(lying[kMask]) ^ (1u << bit));
    expectRejected(withCrc(lying), "the boundary mask marks");
  }
  // A bit past the 18th control point, another one cleared so that the count agrees.
  std::string padded = bytes;
  const std::size_t last = kMask + 2;
  padded[last] = char(std::uint8_t(padded[last]) | 0x80);
  for (std::size_t i = 0; i < 18; ++i)
    if (std::uint8_t(padded[kMask + i / 8]) >> (i % 8) & 1) {
      padded[kMask + i / 8] = char(std::uint8_t(padded[kMask + i / 8]) & ~(1u << (i % 8)));
      break;
    }
  expectRejected(withCrc(padded), "past the last one");
}

TEST(GradientSolidFileMalformed, QuantizationParameters) {
  const GradientSolid solid = smallSolid();
  const std::string bytes = encodeGradientSolid(solid);
  const std::size_t lo = positiveParams(solid), hi = lo + 4, g = lo + 8;
  expectRejected(changed(lo, std::bit_cast<std::uint32_t>(NAN)),
                 "positive sets channel 0: quantization parameters are not finite");
  expectRejected(changed(hi + 12, std::bit_cast<std::uint32_t>(INFINITY)), "positive sets channel 1: quantization");
  expectRejected(changed(g, std::bit_cast<std::uint32_t>(-INFINITY)), "not finite");
  expectRejected(changed(lo, std::bit_cast<std::uint32_t>(std::bit_cast<float>(u32At(bytes, hi)) + 1)), "lo > hi");
  expectRejected(changed(g, std::bit_cast<std::uint32_t>(-1.0f)), "gradient bound is negative");
  // Detail sigma: the last array, 2 channels of parameters then 18 sets of 8 codes.
  const std::size_t detail = bytes.size() - 4 - 18 * 8 - 24;
  expectRejected(changed(detail, std::bit_cast<std::uint32_t>(-0.5f)), "detail sigma channel 0: a standard deviation");
  // Gradient codes stop at 254 (255 levels centred on zero).
  std::string code = bytes;
  code[lo + 24 + 2] = char(255);  // first set's d/du of channel 0
  expectRejected(withCrc(code), "gradient code 255");
}

TEST(GradientSolidFileMalformed, ValidCopyStillDecodes) {
  // The tools above change only what they are asked to: the unchanged file decodes.
  const std::string bytes = encodeGradientSolid(smallSolid());
  EXPECT_NO_THROW(decodeGradientSolid(withCrc(bytes), kWhere));
  EXPECT_EQ(withCrc(bytes), bytes);
}

}  // namespace
}  // namespace texsynth
