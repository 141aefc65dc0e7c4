// 16-bit PNG encoder (stb_image_write only writes 8 bits): per-row adaptive filtering, as
// libpng does, then one zlib stream in a single IDAT chunk.
#include <zlib.h>

#include <array>
#include <cstdlib>
#include <vector>

#include "image_codecs.h"
#include "texsynth/core/error.h"

namespace texsynth::image_codec {
namespace {

void appendBigEndian32(std::string& out, std::uint32_t v) {
  out.push_back(char(v >> 24));
  out.push_back(char(v >> 16));
  out.push_back(char(v >> 8));
  out.push_back(char(v));
}

void appendChunk(std::string& out, const char* type, const std::string& data) {
  appendBigEndian32(out, std::uint32_t(data.size()));
  std::size_t typeAt = out.size();
  out.append(type, 4);
  out += data;
  auto crc = crc32(0L, reinterpret_cast<const Bytef*>(out.data() + typeAt), uInt(4 + data.size()));
  appendBigEndian32(out, std::uint32_t(crc));
}

std::uint8_t paeth(int a, int b, int c) {
  int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return std::uint8_t(a);
  return std::uint8_t(pb <= pc ? b : c);
}

// Filters one row with PNG filter `type` (0..4) into out[0..n).
void filterRow(int type, const std::uint8_t* row, const std::uint8_t* above, std::size_t n, std::size_t stride,
               std::uint8_t* out) {
  for (std::size_t i = 0; i < n; ++i) {
    int left = i >= stride ? row[i - stride] : 0, up = above[i], upLeft = i >= stride ? above[i - stride] : 0;
    int predicted = 0;
    switch (type) {
      case 1:
        predicted = left;
        break;
      case 2:
        predicted = up;
        break;
      case 3:
        predicted = (left + up) / 2;
        break;
      case 4:
        predicted = paeth(left, up, upLeft);
        break;
    }
    out[i] = std::uint8_t(row[i] - predicted);
  }
}

// Raw rows: a filter byte then the filtered samples, the filter chosen per row by the smallest
// sum of absolute (signed) residuals.
std::vector<std::uint8_t> filteredRows(const std::vector<std::uint8_t>& samples, int width, int height, int channels) {
  std::size_t stride = std::size_t(channels) * 2, rowBytes = stride * std::size_t(width);
  std::vector<std::uint8_t> out((rowBytes + 1) * std::size_t(height));
  std::vector<std::uint8_t> zeros(rowBytes, 0), candidate(rowBytes);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = &samples[std::size_t(y) * rowBytes];
    const std::uint8_t* above = y > 0 ? row - rowBytes : zeros.data();
    std::uint8_t* dst = &out[std::size_t(y) * (rowBytes + 1)];
    std::uint64_t bestCost = ~std::uint64_t(0);
    for (int type = 0; type < 5; ++type) {
      filterRow(type, row, above, rowBytes, stride, candidate.data());
      std::uint64_t cost = 0;
      for (std::uint8_t v : candidate) cost += v < 128 ? v : 256 - v;
      if (cost < bestCost) {
        bestCost = cost;
        dst[0] = std::uint8_t(type);
        std::copy(candidate.begin(), candidate.end(), dst + 1);
      }
    }
  }
  return out;
}

}  // namespace

std::string encodePng16(const Image& image) {
  static constexpr std::array<std::uint8_t, 5> kColorType = {0, 0, 4, 2, 6};  // by channel count
  std::vector<std::uint8_t> samples(image.pixels.size() * 2);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    std::uint16_t v = toWord(image.pixels[i]);
    samples[2 * i] = std::uint8_t(v >> 8);  // PNG is big-endian
    samples[2 * i + 1] = std::uint8_t(v);
  }
  std::vector<std::uint8_t> rows = filteredRows(samples, image.width, image.height, image.channels);
  uLongf compressedSize = compressBound(uLong(rows.size()));
  std::string compressed(compressedSize, '\0');
  if (compress2(reinterpret_cast<Bytef*>(compressed.data()), &compressedSize, rows.data(), uLong(rows.size()), 6) !=
      Z_OK)
    throw InternalError("zlib failed to compress PNG data");
  compressed.resize(compressedSize);

  std::string header;
  appendBigEndian32(header, std::uint32_t(image.width));
  appendBigEndian32(header, std::uint32_t(image.height));
  header += {char(16), char(kColorType[image.channels]), 0, 0, 0};  // depth, color, deflate, filter, no interlace
  std::string png("\x89PNG\r\n\x1a\n", 8);
  appendChunk(png, "IHDR", header);
  appendChunk(png, "IDAT", compressed);
  appendChunk(png, "IEND", {});
  return png;
}

}  // namespace texsynth::image_codec
