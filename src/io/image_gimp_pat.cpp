// GIMP pattern (.pat), version 1. All header fields are big-endian 32-bit:
//   header size (including the name), version (1), width, height, bytes per pixel (1..4:
//   gray, gray+alpha, RGB, RGBA), magic "GPAT", then a NUL-terminated UTF-8 name,
// followed by width*height*bytes raw 8-bit pixels, row by row from the top.
#include <cstdint>

#include "image_codecs.h"
#include "texsynth/core/error.h"

namespace texsynth::image_codec {
namespace {

constexpr std::size_t kFixedHeader = 24;

std::uint32_t bigEndian32(std::string_view b, std::size_t at) {
  auto u = [&](std::size_t i) { return std::uint32_t(std::uint8_t(b[at + i])); };
  return u(0) << 24 | u(1) << 16 | u(2) << 8 | u(3);
}

struct PatternHeader {
  std::size_t headerSize = 0;
  int width = 0, height = 0, channels = 0;
};

PatternHeader parseHeader(const std::string& path, std::string_view bytes) {
  if (bytes.size() < kFixedHeader)
    throw InputError(path,
                     "truncated: a GIMP pattern header needs 24 bytes, the file has " + std::to_string(bytes.size()));
  if (bytes.substr(20, 4) != "GPAT") throw InputError(path, "not a GIMP pattern (magic 'GPAT' missing)");
  std::uint32_t headerSize = bigEndian32(bytes, 0), version = bigEndian32(bytes, 4);
  std::uint32_t width = bigEndian32(bytes, 8), height = bigEndian32(bytes, 12), depth = bigEndian32(bytes, 16);
  if (version != 1) throw InputError(path, "unsupported GIMP pattern version " + std::to_string(version) + " (only 1)");
  if (headerSize < kFixedHeader)
    throw InputError(path, "corrupt GIMP pattern: header size " + std::to_string(headerSize) + " is below 24");
  if (headerSize > bytes.size())
    throw InputError(path, "truncated: GIMP pattern header size is " + std::to_string(headerSize) +
                               " bytes but the file has " + std::to_string(bytes.size()));
  if (depth < 1 || depth > 4)
    throw InputError(path, "unsupported GIMP pattern depth of " + std::to_string(depth) + " bytes per pixel (1..4)");
  checkImageSize(path, width, height, depth);
  return {headerSize, int(width), int(height), int(depth)};
}

}  // namespace

ImageFileInfo infoGimpPattern(const std::string& path, std::string_view bytes) {
  PatternHeader header = parseHeader(path, bytes);
  return {header.width, header.height, header.channels, 8, "pat"};
}

Image decodeGimpPattern(const std::string& path, std::string_view bytes) {
  PatternHeader header = parseHeader(path, bytes);
  // The pixels are stored raw: a file too short for them is refused before the image is allocated.
  std::size_t need = std::size_t(header.width) * header.height * header.channels;
  std::size_t have = bytes.size() - header.headerSize;
  if (have < need)
    throw InputError(path, "truncated: header says " + std::to_string(header.width) + "x" +
                               std::to_string(header.height) + " " + describeChannels(header.channels) + " but only " +
                               std::to_string(have) + " bytes of pixel data (need " + std::to_string(need) + ")");
  Image image(header.width, header.height, header.channels);
  const char* pixels = bytes.data() + header.headerSize;
  for (std::size_t i = 0; i < need; ++i) image.pixels[i] = fromByte(std::uint8_t(pixels[i]));
  return image;
}

std::string encodeGimpPattern(const Image& image, const std::string& name) {
  std::string out;
  appendBigEndian32(out, std::uint32_t(kFixedHeader + name.size() + 1));
  appendBigEndian32(out, 1);
  appendBigEndian32(out, std::uint32_t(image.width));
  appendBigEndian32(out, std::uint32_t(image.height));
  appendBigEndian32(out, std::uint32_t(image.channels));
  out += "GPAT";
  out += name;
  out.push_back('\0');
  out.reserve(out.size() + image.pixels.size());
  for (float v : image.pixels) out.push_back(char(toByte(v)));
  return out;
}

}  // namespace texsynth::image_codec
