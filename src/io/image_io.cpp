// Image file dispatch: picks a codec by the file's signature (reading) or extension (writing)
// and holds the limits and checks that every codec shares.
#include "texsynth/io/image_io.h"

#include <cstring>
#include <filesystem>
#include <optional>

#include "image_codecs.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/io/readable_file.h"

namespace texsynth {
namespace image_codec {

const char* formatName(Format format) {
  switch (format) {
    case Format::Png:
      return "png";
    case Format::Jpeg:
      return "jpg";
    case Format::Bmp:
      return "bmp";
    case Format::Tga:
      return "tga";
    case Format::Exr:
      return "exr";
    case Format::Pat:
      return "pat";
  }
  return "?";
}

const char* formatTitle(Format format) {
  switch (format) {
    case Format::Png:
      return "PNG";
    case Format::Jpeg:
      return "JPEG";
    case Format::Bmp:
      return "BMP";
    case Format::Tga:
      return "TGA";
    case Format::Exr:
      return "OpenEXR";
    case Format::Pat:
      return "GIMP pattern";
  }
  return "?";
}

void checkImageSize(const std::string& path, std::int64_t width, std::int64_t height, std::int64_t channels) {
  constexpr std::int64_t kMaxSide = 65536, kMaxValues = std::int64_t(1) << 31;
  std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width <= 0 || height <= 0) throw InputError(path, "invalid image size " + size);
  if (width > kMaxSide || height > kMaxSide)
    throw InputError(path, "image size " + size + " is absurd (more than 65536 pixels per side)");
  if (channels < 1 || channels > 4) throw InputError(path, "unsupported channel count " + std::to_string(channels));
  if (width * height * channels > kMaxValues)
    throw InputError(path,
                     "image size " + size + "x" + std::to_string(channels) + " is absurd (more than 2^31 values)");
}

void checkPlausibleSize(const std::string& path, std::uint64_t fileBytes, int width, int height, int channels,
                        int bytesPerSample, std::uint64_t maxRatio, Format format) {
  std::uint64_t decoded =
      std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(channels) * std::uint64_t(bytesPerSample);
  if (decoded > fileBytes * maxRatio + (std::uint64_t(1) << 20))
    throw InputError(path, "header says " + std::to_string(width) + "x" + std::to_string(height) + " " +
                               describeChannels(channels) + " (" + std::to_string(decoded) +
                               " bytes of pixels) but the file has only " + std::to_string(fileBytes) +
                               " bytes, more than any " + formatTitle(format) + " compression could pack into it");
}

std::string describeChannels(int channels) {
  switch (channels) {
    case 1:
      return "gray";
    case 2:
      return "gray+alpha";
    case 3:
      return "RGB";
    case 4:
      return "RGBA";
  }
  return std::to_string(channels) + "-channel";
}

std::vector<std::uint8_t> quantizedBytes(const Image& image, int channels) {
  Image converted = channels == image.channels ? Image() : image.withChannels(channels);
  const Image& source = channels == image.channels ? image : converted;
  std::vector<std::uint8_t> bytes(source.pixels.size());
  std::size_t rowValues = std::size_t(source.width) * std::size_t(channels);
  parallelFor(0, source.height, [&](std::int64_t y) {
    for (std::size_t i = std::size_t(y) * rowValues, end = i + rowValues; i < end; ++i)
      bytes[i] = toByte(source.pixels[i]);
  });
  return bytes;
}

}  // namespace image_codec

namespace {
using image_codec::Format;

std::optional<Format> formatFromExtension(const std::string& ext) {
  if (ext == "png") return Format::Png;
  if (ext == "jpg" || ext == "jpeg") return Format::Jpeg;
  if (ext == "bmp") return Format::Bmp;
  if (ext == "tga") return Format::Tga;
  if (ext == "exr") return Format::Exr;
  if (ext == "pat") return Format::Pat;
  return std::nullopt;
}

constexpr const char* kSupported = ".png .jpg .jpeg .bmp .tga .exr .pat";

bool startsWith(const std::string& bytes, std::string_view prefix, std::size_t at = 0) {
  return bytes.size() >= at + prefix.size() && std::memcmp(bytes.data() + at, prefix.data(), prefix.size()) == 0;
}

// TGA has no signature, so it is never detected here; the extension decides for it.
std::optional<Format> formatFromSignature(const std::string& bytes) {
  if (startsWith(bytes, "\x89PNG\r\n\x1a\n")) return Format::Png;
  if (startsWith(bytes, "\xff\xd8\xff")) return Format::Jpeg;
  if (startsWith(bytes, "BM")) return Format::Bmp;
  if (startsWith(bytes, std::string_view("\x76\x2f\x31\x01", 4))) return Format::Exr;
  if (startsWith(bytes, "GPAT", 20)) return Format::Pat;
  return std::nullopt;
}

// Reads the file and decides its format; every failure is an InputError naming the file.
Format loadForReading(const std::string& path, std::string& bytes) {
  requireReadableFile(path);  // a directory is that, not an unsupported format
  auto expected = formatFromExtension(fileExtension(path));
  if (!expected)
    throw InputError(path, "unsupported image format '." + fileExtension(path) + "' (readable: " + kSupported + ")");
  bytes = readFileBytes(path);
  if (bytes.empty()) throw InputError(path, "file is empty");
  // Content wins over the name: a JPEG saved as .png still loads.
  if (auto detected = formatFromSignature(bytes)) return *detected;
  if (*expected == Format::Tga) return Format::Tga;
  throw InputError(path,
                   std::string("not a ") + image_codec::formatTitle(*expected) + " file (its signature is missing)");
}

}  // namespace

Image readImage(const std::string& path) {
  std::string bytes;
  Format format = loadForReading(path, bytes);
  switch (format) {
    case Format::Exr:
      return image_codec::decodeExr(path, bytes);
    case Format::Pat:
      return image_codec::decodeGimpPattern(path, bytes);
    default:
      return image_codec::decodeStb(path, bytes, format);
  }
}

std::vector<Image> readImages(const std::vector<std::string>& paths) {
  std::vector<Image> images;
  for (const std::string& path : paths) images.push_back(readImage(path));
  return images;
}

ImageFileInfo readImageInfo(const std::string& path) {
  std::string bytes;
  Format format = loadForReading(path, bytes);
  switch (format) {
    case Format::Exr:
      return image_codec::infoExr(path, bytes);
    case Format::Pat:
      return image_codec::infoGimpPattern(path, bytes);
    default:
      return image_codec::infoStb(path, bytes, format);
  }
}

ImageWriteOptions writeOptionsKeeping(const ImageFileInfo& input) {
  ImageWriteOptions options;
  options.bitsPerChannel = input.bitsPerChannel > 8 ? 16 : 8;
  options.exrHalf = input.bitsPerChannel <= 8;
  return options;
}

std::string encodePngBytes(const Image& image) {
  if (image.empty()) throw ParameterError("image", "cannot encode an empty image");
  return image_codec::encodePng(image, 8);
}

void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options) {
  auto format = formatFromExtension(fileExtension(path));
  if (!format)
    throw ParameterError("output file '" + path + "'",
                         "unsupported image format '." + fileExtension(path) + "' (writable: " + kSupported + ")");
  if (image.empty()) throw ParameterError("image", "cannot write an empty image to '" + path + "'");
  if (image.channels > 4)
    throw ParameterError("image",
                         "cannot write " + std::to_string(image.channels) + " channels to '" + path + "' (1..4)");
  if (image.pixels.size() != image.pixelCount() * image.channels)
    throw ParameterError("image", "pixel buffer size does not match " + std::to_string(image.width) + "x" +
                                      std::to_string(image.height));
  if (image.width > 65536 || image.height > 65536)
    throw ParameterError(
        "image", "too large to write (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
  if (options.bitsPerChannel != 8 && options.bitsPerChannel != 16)
    throw ParameterError("bitsPerChannel", "must be 8 or 16, not " + std::to_string(options.bitsPerChannel));
  if (options.jpegQuality < 1 || options.jpegQuality > 100)
    throw ParameterError("jpegQuality", "must be in 1..100, not " + std::to_string(options.jpegQuality));

  switch (*format) {
    case Format::Exr:
      writeAtomically(
          path, [&](const std::string& temp) { image_codec::writeExr(temp, path, image, options.exrHalf); },
          options.staging);
      return;
    case Format::Pat:
      writeFileAtomically(path, image_codec::encodeGimpPattern(image, std::filesystem::path(path).stem().string()),
                          options.staging);
      return;
    case Format::Png:
      writeFileAtomically(path, image_codec::encodePng(image, options.bitsPerChannel), options.staging);
      return;
    case Format::Jpeg:
      writeFileAtomically(path, image_codec::encodeJpeg(path, image, options.jpegQuality), options.staging);
      return;
    case Format::Bmp:
    case Format::Tga:
      writeFileAtomically(path, image_codec::encodeStb(path, image, *format), options.staging);
      return;
  }
}

}  // namespace texsynth
