#pragma once
// Internal to the io module: one decoder/encoder per image format, called by image_io.cpp,
// plus the size limits and quantization every codec shares.
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/io/image_io.h"

namespace texsynth::image_codec {

enum class Format { Png, Jpeg, Bmp, Tga, Exr, Pat };

// "png", "jpg" ... as reported in ImageFileInfo::format, and upper-case names for messages.
const char* formatName(Format format);
const char* formatTitle(Format format);

// Throws InputError(path, ...) unless 1 <= width,height <= 65536 and the total number of
// values is at most 2^31, so absurd headers are rejected before anything is allocated.
void checkImageSize(const std::string& path, std::int64_t width, std::int64_t height, std::int64_t channels);

// Throws InputError(path, ...) if a header declares more pixel data than `fileBytes` could
// hold at the format's best possible compression ratio (deflate, for instance, never beats
// ~1032:1): a tiny file claiming a huge image is rejected before anything is allocated.
void checkPlausibleSize(const std::string& path, std::uint64_t fileBytes, int width, int height, int channels,
                        int bytesPerSample, std::uint64_t maxRatio, Format format);

// "1 channel" / "RGB" ... for messages about the pixel layout.
std::string describeChannels(int channels);

// Quantization to the integer range of a format; clips to [0,1] and maps NaN to 0.
// std::lround for 0 <= x < 2^23, inlined and vectorizable (lround is a library call):
// x - trunc(x) is exact in float, so this rounds halves up exactly as lround does.
inline int roundNonNegative(float x) {
  int whole = int(x);
  return whole + int(x - float(whole) >= 0.5f);
}
inline std::uint8_t toByte(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 255;
  return std::uint8_t(roundNonNegative(v * 255.0f));
}
// The value every 8-bit reader gives level k: k/255 rounded to float.
inline float fromByte(std::uint8_t k) {
  return float(k) * (1.0f / 255.0f);
}
inline std::uint16_t toWord(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 65535;
  return std::uint16_t(roundNonNegative(v * 65535.0f));
}

// Appends v as four big-endian bytes (PNG and zlib store integers so).
inline void appendBigEndian32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char(v >> shift));
}

// The image converted to `channels` channels (Image::withChannels) and quantized to bytes,
// in parallel, for the 8-bit encoders.
std::vector<std::uint8_t> quantizedBytes(const Image& image, int channels);

// stb decodes PNG, JPEG, BMP and TGA. `bytes` is the whole file.
ImageFileInfo infoStb(const std::string& path, std::string_view bytes, Format format);
Image decodeStb(const std::string& path, std::string_view bytes, Format format);
// 8-bit BMP / TGA file contents (channel conversions as documented in image_io.h).
std::string encodeStb(const std::string& path, const Image& image, Format format);

// PNG file contents, 8 or 16 bits per channel, deflated in parallel.
std::string encodePng(const Image& image, int bitsPerChannel);

// Baseline JPEG file contents (libjpeg-turbo), always RGB; quality 1..100.
std::string encodeJpeg(const std::string& path, const Image& image, int quality);

// OpenEXR.
ImageFileInfo infoExr(const std::string& path, std::string_view bytes);
Image decodeExr(const std::string& path, std::string_view bytes);
// Writes an EXR to `filePath` (the temporary path of an atomic write): half floats when every
// value is an 8-bit level, else 32-bit floats; lossless either way (see image_exr_write.cpp).
void writeExr(const std::string& filePath, const std::string& path, const Image& image, bool halfPrecision);

// GIMP .pat patterns.
ImageFileInfo infoGimpPattern(const std::string& path, std::string_view bytes);
Image decodeGimpPattern(const std::string& path, std::string_view bytes);
std::string encodeGimpPattern(const Image& image, const std::string& name);

}  // namespace texsynth::image_codec
