// PNG, JPEG, BMP and TGA decoding through stb_image; BMP and TGA encoding through
// stb_image_write (implementations live in Debian's libstb). PNG and JPEG have faster encoders
// of their own: image_png.cpp and image_jpeg.cpp. stb is lenient with truncated files (it pads
// with zeros), so before decoding we check that the file's structure is complete; see
// image_stb_checks.cpp.
#include <stb_image.h>
#include <stb_image_write.h>

#include <climits>
#include <cstdlib>
#include <memory>

#include "image_codecs.h"
#include "image_stb_checks.h"
#include "texsynth/core/error.h"

namespace texsynth::image_codec {
namespace {

struct StbFree {
  void operator()(void* data) const { stbi_image_free(data); }
};

int byteLength(const std::string& path, std::string_view bytes, Format format) {
  if (bytes.size() > std::size_t(INT_MAX))
    throw InputError(path, std::string("file is too large for the ") + formatTitle(format) + " decoder");
  return int(bytes.size());
}

std::string decodeFailure(Format format) {
  const char* reason = stbi_failure_reason();
  return std::string("cannot decode ") + formatTitle(format) + ": " + (reason ? reason : "unknown error");
}

const stbi_uc* data(std::string_view bytes) {
  return reinterpret_cast<const stbi_uc*>(bytes.data());
}

void appendBytes(void* context, void* bytes, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(bytes), std::size_t(size));
}

// The channel count each 8-bit writer stores for `channels` given channels.
int storedChannels(Format format, int channels) {
  if (format == Format::Bmp) return channels == 2 || channels == 4 ? 4 : 3;
  return channels;
}

}  // namespace

ImageFileInfo infoStb(const std::string& path, std::string_view bytes, Format format) {
  int length = byteLength(path, bytes, format);
  checkDeclaredSize(path, bytes, format);
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data(bytes), length, &width, &height, &channels))
    throw InputError(path, decodeFailure(format));
  // stb's BMP info reports a top-down file's height as stored, negative; its loader flips it.
  if (format == Format::Bmp) height = std::abs(height);
  checkImageSize(path, width, height, channels);
  bool sixteen = stbi_is_16_bit_from_memory(data(bytes), length);
  // A baseline JPEG spends at least a bit or two per 8x8 block. PNG is checked by
  // checkDeclaredSize, BMP and TGA exactly by checkStbStructure.
  if (format == Format::Jpeg) checkPlausibleSize(path, bytes.size(), width, height, channels, 1, 2048, format);
  return {width, height, channels, sixteen ? 16 : 8, formatName(format)};
}

Image decodeStb(const std::string& path, std::string_view bytes, Format format) {
  ImageFileInfo info = infoStb(path, bytes, format);
  checkStbStructure(path, bytes, format, info.width, info.height, info.channels);
  int length = int(bytes.size());
  int width = 0, height = 0, channels = 0;
  Image image;
  if (info.bitsPerChannel == 16) {
    std::unique_ptr<stbi_us, StbFree> pixels(
        stbi_load_16_from_memory(data(bytes), length, &width, &height, &channels, 0));
    if (!pixels) throw InputError(path, decodeFailure(format));
    image = Image(width, height, channels);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(pixels.get()[i]) * (1.0f / 65535.0f);
  } else {
    std::unique_ptr<stbi_uc, StbFree> pixels(stbi_load_from_memory(data(bytes), length, &width, &height, &channels, 0));
    if (!pixels) throw InputError(path, decodeFailure(format));
    image = Image(width, height, channels);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = fromByte(pixels.get()[i]);
  }
  if (width != info.width || height != info.height || channels != info.channels)
    throw InputError(path, "decoded size differs from the header's");
  return image;
}

std::string encodeStb(const std::string& path, const Image& image, Format format) {
  int channels = storedChannels(format, image.channels);
  std::vector<std::uint8_t> quantized = quantizedBytes(image, channels);

  std::string bytes;
  int w = image.width, h = image.height, ok = 0;
  switch (format) {
    case Format::Bmp:
      ok = stbi_write_bmp_to_func(appendBytes, &bytes, w, h, channels, quantized.data());
      break;
    case Format::Tga:
      ok = stbi_write_tga_to_func(appendBytes, &bytes, w, h, channels, quantized.data());
      break;
    default:
      break;
  }
  if (!ok || bytes.empty()) throw OutputError(path, std::string("the ") + formatTitle(format) + " encoder failed");
  return bytes;
}

}  // namespace texsynth::image_codec
