// The image encoders: PNG (8 and 16 bit, deflated in parallel), OpenEXR (half for 8-bit
// levels, float otherwise), JPEG (libjpeg-turbo); plus top-down BMP input and the options that
// keep a 16-bit input's depth.
#include <OpenEXR/ImfRgbaFile.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <filesystem>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/io/image_io.h"

namespace texsynth {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

// Every value is exactly k / levels (as the 8- and 16-bit readers compute it), k pseudo-random,
// so a lossless round trip gives back exactly the same floats.
Image levelsImage(int width, int height, int channels, int levels, unsigned seed = 1) {
  Image image(width, height, channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    auto k = std::uint32_t(uniform01(hashKey(seed, i)) * float(levels + 1));
    image.pixels[i] = float(std::min<std::uint32_t>(k, levels)) * (1.0f / float(levels));
  }
  return image;
}

std::uint32_t bigEndian32(const std::string& bytes, std::size_t at) {
  auto u = [&](std::size_t i) { return std::uint32_t(std::uint8_t(bytes[at + i])); };
  return u(0) << 24 | u(1) << 16 | u(2) << 8 | u(3);
}

// Checks what stb does not: every chunk's CRC, and that the IDAT data is one zlib stream
// (adler32 included) of exactly a filter byte plus `rowBytes` per row, filters 0..4.
void expectValidPngContainer(const std::string& png, std::size_t rowBytes, int height) {
  std::string stream;
  std::size_t at = 8;
  bool ended = false;
  while (!ended) {
    ASSERT_LE(at + 12, png.size());
    std::uint32_t length = bigEndian32(png, at);
    std::string type = png.substr(at + 4, 4);
    ASSERT_LE(at + 12 + length, png.size());
    uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(png.data() + at + 4), uInt(4 + length));
    EXPECT_EQ(bigEndian32(png, at + 8 + length), std::uint32_t(crc)) << "CRC of " << type;
    if (type == "IDAT") stream.append(png, at + 8, length);
    ended = type == "IEND";
    at += 12 + length;
  }
  EXPECT_EQ(at, png.size());
  std::string raw((rowBytes + 1) * std::size_t(height) + 1, '\0');
  uLongf rawSize = uLongf(raw.size());
  ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(raw.data()), &rawSize, reinterpret_cast<const Bytef*>(stream.data()),
                       uLong(stream.size())),
            Z_OK);
  ASSERT_EQ(rawSize, (rowBytes + 1) * std::size_t(height));
  for (int y = 0; y < height; ++y) EXPECT_LE(std::uint8_t(raw[std::size_t(y) * (rowBytes + 1)]), 4) << "row " << y;
}

struct Shape {
  int width, height;
};

// 1x1, single rows and columns, odd sizes, and filtered data of exactly one and two 1 MiB
// deflate chunks (1023 bytes + a filter byte per row) and just over.
const Shape kShapes[] = {{1, 1}, {1, 37}, {53, 1}, {7, 5}, {31, 17}, {1023, 1024}, {1023, 2048}, {1023, 1025}};

TEST(ImageEncoders, PngRoundTripsBitExactAtEveryDepthChannelCountAndChunkBoundary) {
  TempDir dir;
  for (int bits : {8, 16})
    for (int channels = 1; channels <= 4; ++channels)
      for (Shape shape : kShapes) {
        int width = shape.width;
        if (shape.width == 1023 && (channels > 1 || bits == 16)) continue;  // big shapes: gray 8-bit only
        SCOPED_TRACE(std::to_string(bits) + " bit, " + std::to_string(channels) + " channels, " +
                     std::to_string(width) + "x" + std::to_string(shape.height));
        Image image = levelsImage(width, shape.height, channels, bits == 8 ? 255 : 65535, unsigned(width + channels));
        std::string path = dir.file("p.png");
        writeImage(path, image, {.bitsPerChannel = bits});
        Image back = readImage(path);
        ASSERT_EQ(back.channels, channels);
        ASSERT_EQ(back.width, width);
        ASSERT_EQ(back.height, shape.height);
        EXPECT_TRUE(back.pixels == image.pixels);
        EXPECT_EQ(readImageInfo(path).bitsPerChannel, bits);
        expectValidPngContainer(readFileBytes(path), std::size_t(width) * channels * (bits / 8), shape.height);
      }
}

TEST(ImageEncoders, PngAndExrBytesDoNotDependOnTheThreadCount) {
  TempDir dir;
  // Several deflate chunks (and OpenEXR line blocks) of smooth, compressible data.
  Image smooth = test::makeTestPattern(640, 480, 4);
  Image levels = levelsImage(720, 540, 3, 255);
  struct Case {
    std::string name;
    const Image& image;
    int bits;
  };
  for (const Case& c : {Case{"a.png", smooth, 8}, Case{"b.png", smooth, 16}, Case{"c.png", levels, 8},
                        Case{"d.exr", smooth, 8}, Case{"e.exr", levels, 8}}) {
    std::string bytes[3];
    int threads[3] = {1, 2, 0};
    for (int i = 0; i < 3; ++i) {
      ThreadLimit limit(threads[i]);
      writeImage(dir.file(c.name), c.image, {.bitsPerChannel = c.bits});
      bytes[i] = readFileBytes(dir.file(c.name));
    }
    EXPECT_TRUE(bytes[0] == bytes[1]) << c.name;
    EXPECT_TRUE(bytes[0] == bytes[2]) << c.name;
  }
}

TEST(ImageEncoders, ExrStoresEightBitLevelsAsHalfAndReadsThemBackExactly) {
  TempDir dir;
  for (int channels = 1; channels <= 4; ++channels) {
    Image image = levelsImage(37, 29, channels, 255, unsigned(channels));
    std::string path = dir.file("levels.exr");
    writeImage(path, image);
    EXPECT_EQ(readImageInfo(path).bitsPerChannel, 16);
    Image back = readImage(path);
    ASSERT_EQ(back.channels, channels);
    EXPECT_TRUE(back.pixels == image.pixels);
  }
  // Other readers see the nearest half floats, which still round to the same 8-bit levels.
  Image rgba = levelsImage(11, 7, 4, 255, 9);
  writeImage(dir.file("rgba.exr"), rgba);
  Imf::RgbaInputFile file(dir.file("rgba.exr").c_str());
  std::vector<Imf::Rgba> pixels(11 * 7);
  file.setFrameBuffer(pixels.data(), 1, 11);
  file.readPixels(0, 6);
  for (int i = 0; i < 11 * 7; ++i) {
    EXPECT_NEAR(float(pixels[i].r), rgba.pixels[4 * i], 0.5f / 255.0f);
    EXPECT_NEAR(float(pixels[i].a), rgba.pixels[4 * i + 3], 0.5f / 255.0f);
  }
}

TEST(ImageEncoders, ExrKeepsExactFloatsUnlessEveryValueIsAnEightBitLevel) {
  TempDir dir;
  Image coordinates(13, 9, 2);  // as `texsynth image --coords` writes them: pixel positions
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 13; ++x) coordinates.at(x, y, 0) = float(x), coordinates.at(x, y, 1) = float(y);
  Image almost = levelsImage(13, 9, 3, 255);
  almost.pixels[40] = 0.5f;  // 127.5 / 255: between two levels
  Image negativeZero = levelsImage(13, 9, 1, 255);
  negativeZero.pixels[3] = -0.0f;
  for (const Image* image : {&coordinates, &almost, &negativeZero}) {
    writeImage(dir.file("f.exr"), *image);
    EXPECT_EQ(readImageInfo(dir.file("f.exr")).bitsPerChannel, 32);
    Image back = readImage(dir.file("f.exr"));
    ASSERT_EQ(back.pixels.size(), image->pixels.size());
    EXPECT_EQ(std::memcmp(back.pixels.data(), image->pixels.data(), image->pixels.size() * sizeof(float)), 0);
  }
}

// The luma component's sampling factors in a baseline JPEG's frame header (0x11 or 0x22).
int lumaSampling(const std::string& jpeg) {
  std::size_t frame = jpeg.find("\xff\xc0");
  return frame == std::string::npos ? -1 : std::uint8_t(jpeg[frame + 11]);
}

TEST(ImageEncoders, JpegIsReadableWithTheRightSizeAndChromaAsBefore) {
  TempDir dir;
  for (int channels = 1; channels <= 4; ++channels)
    for (Shape shape : {Shape{1, 1}, Shape{17, 9}, Shape{64, 48}, Shape{3, 130}}) {
      std::string path = dir.file("j.jpg");
      writeImage(path, test::makeTestPattern(shape.width, shape.height, 3).withChannels(channels));
      Image back = readImage(path);
      EXPECT_EQ(back.width, shape.width);
      EXPECT_EQ(back.height, shape.height);
      EXPECT_EQ(back.channels, 3);
    }
  // Full-resolution chroma above quality 90, 2x2 subsampled at 90 and below, as stb did.
  Image image = test::makeTestPattern(40, 30, 5);
  writeImage(dir.file("high.jpg"), image, {.jpegQuality = 91});
  writeImage(dir.file("low.jpg"), image, {.jpegQuality = 90});
  EXPECT_EQ(lumaSampling(readFileBytes(dir.file("high.jpg"))), 0x11);
  EXPECT_EQ(lumaSampling(readFileBytes(dir.file("low.jpg"))), 0x22);
}

// The same BMP stored top-down: rows reversed and the height negated.
std::string topDown(const std::string& bmp) {
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, bmp.data() + at, 4);  // little-endian host, as the test machines are
    return v;
  };
  std::size_t offset = u32(10), width = u32(18), height = u32(22), bits = std::uint16_t(u32(28));
  std::size_t rowBytes = (width * bits + 31) / 32 * 4;
  std::string flipped = bmp;
  for (std::size_t y = 0; y < height; ++y)
    flipped.replace(offset + y * rowBytes, rowBytes, bmp, offset + (height - 1 - y) * rowBytes, rowBytes);
  std::int32_t negative = -std::int32_t(height);
  std::memcpy(flipped.data() + 22, &negative, 4);
  return flipped;
}

TEST(ImageEncoders, TopDownBmpLoadsTheSamePixelsAsBottomUp) {
  TempDir dir;
  for (int channels : {3, 4}) {
    Image image = levelsImage(13, 7, channels, 255, unsigned(channels));
    writeImage(dir.file("up.bmp"), image);
    test::writeBytes(dir.file("down.bmp"), topDown(readFileBytes(dir.file("up.bmp"))));
    ImageFileInfo info = readImageInfo(dir.file("down.bmp"));
    EXPECT_EQ(info.width, 13);
    EXPECT_EQ(info.height, 7);
    Image down = readImage(dir.file("down.bmp"));
    EXPECT_TRUE(down.pixels == image.pixels) << channels << " channels";
  }
}

TEST(ImageEncoders, WriteOptionsKeepASixteenBitInputsDepth) {
  TempDir dir;
  Image image = levelsImage(9, 8, 3, 65535);
  writeImage(dir.file("deep.png"), image, {.bitsPerChannel = 16});
  writeImage(dir.file("shallow.png"), image);
  writeImage(dir.file("float.exr"), image);
  EXPECT_EQ(writeOptionsKeeping(readImageInfo(dir.file("deep.png"))).bitsPerChannel, 16);
  EXPECT_EQ(writeOptionsKeeping(readImageInfo(dir.file("shallow.png"))).bitsPerChannel, 8);
  EXPECT_EQ(writeOptionsKeeping(readImageInfo(dir.file("float.exr"))).bitsPerChannel, 16);
  // A 16-bit input written with them round-trips exactly.
  Image deep = readImage(dir.file("deep.png"));
  writeImage(dir.file("again.png"), deep, writeOptionsKeeping(readImageInfo(dir.file("deep.png"))));
  EXPECT_TRUE(readImage(dir.file("again.png")).pixels == image.pixels);
}

}  // namespace
}  // namespace texsynth
