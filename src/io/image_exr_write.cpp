// OpenEXR writer. Images whose every value is an 8-bit level (anything read from an 8-bit file
// and resampled without interpolation) are stored as half floats, half the size, tagged so
// that our reader restores them exactly; anything else as 32-bit floats (both lossless), or as
// half floats when the caller says the data has no more precision than that (an output made
// from 8-bit exemplars: half's 11-bit mantissa keeps more than their 8 bits).
#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>

#include <array>
#include <atomic>
#include <cmath>
#include <vector>

#include "image_codecs.h"
#include "image_exr_support.h"
#include "texsynth/core/error.h"

namespace texsynth::image_codec {
namespace {

// Chosen by measurement on 4096^2 textures: PIZ (lossless wavelet + Huffman) beats ZIP at every
// zlib level on both size and time, for half floats (54 MB vs 71 MB, 2.6x less CPU) and for
// 32-bit floats (150 MB vs 172 MB, 1.5x less CPU); RLE and ZIPS compress less.
constexpr Imf::Compression kCompression = Imf::PIZ_COMPRESSION;

// True if every value is exactly k/255 for an integer k in 0..255 (so not NaN, not -0).
bool holdsEightBitLevels(const Image& image) {
  std::atomic<bool> levels{true};
  std::size_t rowValues = std::size_t(image.width) * std::size_t(image.channels);
  parallelForChunks(0, image.height, 64, [&](std::int64_t begin, std::int64_t end) {
    if (!levels.load(std::memory_order_relaxed)) return;
    for (std::size_t i = std::size_t(begin) * rowValues; i < std::size_t(end) * rowValues; ++i) {
      float v = image.pixels[i];
      if (fromByte(toByte(v)) != v || std::signbit(v)) {
        levels = false;
        return;
      }
    }
  });
  return levels;
}

// Exact levels go through a table (the reader snaps them back); other values round to nearest.
std::vector<half> toHalves(const Image& image, bool levels) {
  std::array<half, 256> table;
  for (int k = 0; k < 256; ++k) table[k] = half(fromByte(std::uint8_t(k)));
  std::vector<half> halves(image.pixels.size());
  std::size_t rowValues = std::size_t(image.width) * std::size_t(image.channels);
  parallelFor(0, image.height, [&](std::int64_t y) {
    for (std::size_t i = std::size_t(y) * rowValues, end = i + rowValues; i < end; ++i)
      halves[i] = levels ? table[toByte(image.pixels[i])] : half(image.pixels[i]);
  });
  return halves;
}

}  // namespace

void writeExr(const std::string& filePath, const std::string& path, const Image& image, bool halfPrecision) {
  static const std::vector<std::vector<const char*>> kNames = {
      {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
  const std::vector<const char*>& names = kNames[image.channels - 1];
  const bool levels = holdsEightBitLevels(image), useHalf = levels || halfPrecision;
  std::vector<half> halves = useHalf ? toHalves(image, levels) : std::vector<half>();
  Imf::PixelType type = useHalf ? Imf::HALF : Imf::FLOAT;
  std::size_t sampleBytes = useHalf ? sizeof(half) : sizeof(float);
  // Only read by the writer.
  char* base = useHalf ? reinterpret_cast<char*>(halves.data())
                       : reinterpret_cast<char*>(const_cast<float*>(image.pixels.data()));
  try {
    matchExrThreadsToLimit();
    Imf::Header header(image.width, image.height);
    header.compression() = kCompression;
    if (levels) header.insert(kExrLevelsAttribute, Imf::IntAttribute(kEightBitLevels));
    for (const char* name : names) header.channels().insert(name, Imf::Channel(type));
    std::size_t xStride = sampleBytes * image.channels, yStride = xStride * image.width;
    Imf::FrameBuffer frame;
    for (int c = 0; c < image.channels; ++c)
      frame.insert(names[c], Imf::Slice(type, base + c * sampleBytes, xStride, yStride));
    Imf::OutputFile file(filePath.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw OutputError(path, std::string("cannot write OpenEXR: ") + e.what());
  }
}

}  // namespace texsynth::image_codec
