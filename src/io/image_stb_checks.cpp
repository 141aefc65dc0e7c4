#include "image_stb_checks.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "texsynth/core/error.h"

namespace texsynth::image_codec {
namespace {

std::uint32_t bigEndian32(std::string_view b, std::size_t at) {
  auto u = [&](std::size_t i) { return std::uint32_t(std::uint8_t(b[at + i])); };
  return u(0) << 24 | u(1) << 16 | u(2) << 8 | u(3);
}
std::uint32_t littleEndian32(std::string_view b, std::size_t at) {
  auto u = [&](std::size_t i) { return std::uint32_t(std::uint8_t(b[at + i])); };
  return u(3) << 24 | u(2) << 16 | u(1) << 8 | u(0);
}
std::uint16_t littleEndian16(std::string_view b, std::size_t at) {
  return std::uint16_t(std::uint8_t(b[at]) | std::uint8_t(b[at + 1]) << 8);
}

[[noreturn]] void shortPixelData(const std::string& path, int width, int height, int channels, std::uint64_t have,
                                 std::uint64_t need) {
  throw InputError(path, "truncated: header says " + std::to_string(width) + "x" + std::to_string(height) + " " +
                             describeChannels(channels) + " but only " + std::to_string(have) +
                             " bytes of pixel data (need " + std::to_string(need) + ")");
}

// Every chunk must fit in the file, up to and including IEND.
void checkPng(const std::string& path, std::string_view bytes) {
  std::size_t at = 8;
  while (at + 8 <= bytes.size()) {
    std::uint64_t length = bigEndian32(bytes, at);
    std::string type(bytes.substr(at + 4, 4));
    if (length > 0x7fffffffu) throw InputError(path, "corrupt PNG: chunk '" + type + "' has an impossible length");
    std::uint64_t end = at + 8 + length + 4;  // data and CRC
    if (end > bytes.size())
      throw InputError(path, "truncated: the file ends inside PNG chunk '" + type + "' (" +
                                 std::to_string(bytes.size() - at) + " of " + std::to_string(end - at) + " bytes)");
    if (type == "IEND") return;
    at = std::size_t(end);
  }
  throw InputError(path, "truncated: the PNG file ends before its IEND chunk");
}

// Scan data cannot contain FF DA or FF D9 (0xFF is byte-stuffed), so a complete file has an
// end-of-image marker after its last start-of-scan marker.
void checkJpeg(const std::string& path, std::string_view bytes) {
  std::size_t lastScan = bytes.rfind("\xff\xda");
  if (lastScan == std::string_view::npos) throw InputError(path, "truncated: the JPEG file has no image scan");
  if (bytes.find("\xff\xd9", lastScan) == std::string_view::npos)
    throw InputError(path, "truncated: the JPEG file ends inside its image data (no end-of-image marker)");
}

void checkBmp(const std::string& path, std::string_view bytes, int width, int height, int channels) {
  if (bytes.size() < 30) throw InputError(path, "truncated: the BMP header is incomplete");
  std::uint32_t pixelOffset = littleEndian32(bytes, 10);
  std::uint32_t headerSize = littleEndian32(bytes, 14);
  std::uint32_t bitsPerPixel = headerSize == 12 ? littleEndian16(bytes, 24) : littleEndian16(bytes, 28);
  std::uint32_t compression = headerSize >= 40 && bytes.size() >= 34 ? littleEndian32(bytes, 30) : 0;
  bool uncompressed = compression == 0 || compression == 3 || compression == 6;
  if (!uncompressed) return;  // RLE: stb rejects these itself
  std::uint64_t rowBytes = (std::uint64_t(width) * bitsPerPixel + 31) / 32 * 4;
  std::uint64_t need = rowBytes * std::uint64_t(height);
  std::uint64_t have = bytes.size() > pixelOffset ? bytes.size() - pixelOffset : 0;
  if (have < need) shortPixelData(path, width, height, channels, have, need);
}

void checkTga(const std::string& path, std::string_view bytes, int width, int height, int channels) {
  if (bytes.size() < 18) throw InputError(path, "truncated: the TGA header is incomplete");
  auto u8 = [&](std::size_t i) { return std::uint32_t(std::uint8_t(bytes[i])); };
  std::uint32_t imageType = u8(2), bitsPerPixel = u8(16);
  std::uint64_t paletteBytes = u8(1) == 1 ? std::uint64_t(littleEndian16(bytes, 5)) * ((u8(7) + 7) / 8) : 0;
  std::uint64_t at = 18 + u8(0) + paletteBytes;
  std::uint64_t pixelBytes = (bitsPerPixel + 7) / 8;
  std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  std::uint64_t have = bytes.size() > at ? bytes.size() - at : 0;
  if (imageType < 8) {
    if (have < pixels * pixelBytes) shortPixelData(path, width, height, channels, have, pixels * pixelBytes);
    return;
  }
  // Run-length packets: a header byte, then one pixel (a run) or `count` raw pixels.
  std::uint64_t covered = 0;
  while (covered < pixels) {
    if (at >= bytes.size())
      throw InputError(path, "truncated: TGA run-length data ends after " + std::to_string(covered) + " of " +
                                 std::to_string(pixels) + " pixels");
    std::uint32_t packet = u8(std::size_t(at++));
    std::uint64_t count = (packet & 0x7f) + 1;
    at += (packet & 0x80) ? pixelBytes : count * pixelBytes;
    if (at > bytes.size())
      throw InputError(path, "truncated: TGA run-length data ends inside a packet after " + std::to_string(covered) +
                                 " of " + std::to_string(pixels) + " pixels");
    covered += count;
  }
}

}  // namespace

void checkDeclaredSize(const std::string& path, std::string_view bytes, Format format) {
  auto u8 = [&](std::size_t i) { return std::int64_t(std::uint8_t(bytes[i])); };
  if (format == Format::Png && bytes.size() >= 26 && bytes.substr(12, 4) == "IHDR") {
    static constexpr int kChannelsOfColorType[7] = {1, 1, 3, 3, 2, 1, 4};
    int channels = u8(25) < 7 ? kChannelsOfColorType[u8(25)] : 1, sampleBytes = u8(24) == 16 ? 2 : 1;
    std::int64_t width = bigEndian32(bytes, 16), height = bigEndian32(bytes, 20);
    checkImageSize(path, width, height, channels);
    checkPlausibleSize(path, bytes.size(), int(width), int(height), channels, sampleBytes, 1100,
                       format);  // deflate: ~1032:1 at best
    if (width * height * channels * sampleBytes > (std::int64_t(1) << 30))
      throw InputError(path, "PNG of " + std::to_string(width) + "x" + std::to_string(height) +
                                 " is too large for the decoder (stb reads at most 1 GiB of pixels)");
  } else if (format == Format::Bmp && bytes.size() >= 26) {
    bool os2 = littleEndian32(bytes, 14) == 12;
    std::int64_t width = os2 ? littleEndian16(bytes, 18) : std::int32_t(littleEndian32(bytes, 18));
    std::int64_t height = os2 ? littleEndian16(bytes, 20) : std::int32_t(littleEndian32(bytes, 22));
    checkImageSize(path, width, std::abs(height), 3);  // negative height: rows stored top-down
  } else if (format == Format::Tga && bytes.size() >= 18) {
    std::int64_t channels = std::clamp<std::int64_t>(u8(16) / 8, 1, 4);
    checkImageSize(path, littleEndian16(bytes, 12), littleEndian16(bytes, 14), channels);
  }
}

void checkStbStructure(const std::string& path, std::string_view bytes, Format format, int width, int height,
                       int channels) {
  switch (format) {
    case Format::Png:
      checkPng(path, bytes);
      break;
    case Format::Jpeg:
      checkJpeg(path, bytes);
      break;
    case Format::Bmp:
      checkBmp(path, bytes, width, height, channels);
      break;
    case Format::Tga:
      checkTga(path, bytes, width, height, channels);
      break;
    default:
      break;
  }
}

}  // namespace texsynth::image_codec
