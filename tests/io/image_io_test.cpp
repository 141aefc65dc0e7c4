// Image I/O: round trips for every format and depth, the real GIMP patterns, malformed and
// truncated files, atomic writes and deterministic output.
#include "texsynth/io/image_io.h"

#include <OpenEXR/ImfRgbaFile.h>
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/random.h"

namespace texsynth {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

// A test pattern with `channels` channels whose alpha (if any) varies too.
Image patternWithChannels(int width, int height, int channels, unsigned seed = 1) {
  Image rgb = test::makeTestPattern(width, height, seed);
  Image image = rgb.withChannels(channels);
  if (channels == 2 || channels == 4)
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) image.at(x, y, channels - 1) = uniform01(hashKey(seed + 7, latticeId(x, y)));
  return image;
}

float quantized(float v, float levels) {
  return std::round(std::clamp(v, 0.0f, 1.0f) * levels) / levels;
}

// Every value of `actual` equals `expected` quantized to `levels` (255 or 65535).
void expectQuantizedEqual(const Image& expected, const Image& actual, float levels) {
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  ASSERT_EQ(actual.channels, expected.channels);
  for (std::size_t i = 0; i < expected.pixels.size(); ++i)
    ASSERT_NEAR(actual.pixels[i], quantized(expected.pixels[i], levels), 1e-6f) << "value " << i;
}

double meanAbsoluteError(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(a.pixels[i] - b.pixels[i]);
  return sum / double(a.pixels.size());
}

std::string readBytes(const std::string& path) {
  return readFileBytes(path);
}

// readImage must throw exactly one InputError that names the file and contains `problem`.
void expectReadError(const std::string& path, const std::string& problem = "") {
  test::expectInputError([&] { readImage(path); }, path, problem);
}

TEST(ImageIo, PngRoundTripsEightBitForEveryChannelCount) {
  TempDir dir;
  for (int channels = 1; channels <= 4; ++channels) {
    Image image = patternWithChannels(37, 23, channels);
    std::string path = dir.file("c" + std::to_string(channels) + ".png");
    writeImage(path, image);
    expectQuantizedEqual(image, readImage(path), 255.0f);
    ImageFileInfo info = readImageInfo(path);
    EXPECT_EQ(info.width, 37);
    EXPECT_EQ(info.height, 23);
    EXPECT_EQ(info.channels, channels);
    EXPECT_EQ(info.bitsPerChannel, 8);
    EXPECT_EQ(info.format, "png");
  }
}

TEST(ImageIo, PngRoundTripsSixteenBitExactly) {
  TempDir dir;
  for (int channels = 1; channels <= 4; ++channels) {
    Image image = patternWithChannels(41, 19, channels, 3);
    std::string path = dir.file("c" + std::to_string(channels) + ".png");
    writeImage(path, image, {.bitsPerChannel = 16});
    Image back = readImage(path);
    expectQuantizedEqual(image, back, 65535.0f);
    EXPECT_EQ(readImageInfo(path).bitsPerChannel, 16);
  }
}

TEST(ImageIo, TgaAndBmpRoundTripEightBit) {
  TempDir dir;
  for (int channels = 1; channels <= 4; ++channels) {
    Image image = patternWithChannels(29, 31, channels, 5);
    std::string tga = dir.file("c" + std::to_string(channels) + ".tga");
    writeImage(tga, image);
    expectQuantizedEqual(image, readImage(tga), 255.0f);
    EXPECT_EQ(readImageInfo(tga).format, "tga");

    // BMP stores RGB or RGBA: gray is expanded, gray+alpha becomes RGBA.
    std::string bmp = dir.file("c" + std::to_string(channels) + ".bmp");
    writeImage(bmp, image);
    int stored = channels == 2 || channels == 4 ? 4 : 3;
    expectQuantizedEqual(image.withChannels(stored), readImage(bmp), 255.0f);
  }
}

TEST(ImageIo, JpegRoundTripIsClose) {
  TempDir dir;
  Image image = test::makeTestPattern(64, 48, 2);
  std::string path = dir.file("p.jpg");
  writeImage(path, image, {.jpegQuality = 95});
  Image back = readImage(path);
  ASSERT_EQ(back.channels, 3);
  EXPECT_LT(meanAbsoluteError(image, back), 0.03);
  // Lower quality is smaller and worse.
  std::string low = dir.file("low.jpeg");
  writeImage(low, image, {.jpegQuality = 10});
  EXPECT_LT(fs::file_size(low), fs::file_size(path));
  EXPECT_GT(meanAbsoluteError(image, readImage(low)), meanAbsoluteError(image, back));
  // JPEG has no alpha, and stb stores gray as color: both come back as RGB.
  writeImage(path, patternWithChannels(16, 16, 4));
  EXPECT_EQ(readImage(path).channels, 3);
  Image grayAlpha = patternWithChannels(16, 16, 2);
  writeImage(path, grayAlpha);
  Image gray = readImage(path);
  ASSERT_EQ(gray.channels, 3);
  EXPECT_LT(meanAbsoluteError(grayAlpha.withChannels(3), gray), 0.03);
  EXPECT_NEAR(gray.at(5, 7, 0), gray.at(5, 7, 2), 2.0f / 255.0f);
}

TEST(ImageIo, ExrRoundTripsFloatExactlyIncludingHdrValues) {
  TempDir dir;
  for (int channels = 1; channels <= 4; ++channels) {
    Image image = patternWithChannels(23, 17, channels, 9);
    image.pixels[0] = -0.5f;
    image.pixels[1] = 37.25f;
    image.pixels[2] = 1e-9f;
    std::string path = dir.file("c" + std::to_string(channels) + ".exr");
    writeImage(path, image);
    Image back = readImage(path);
    ASSERT_EQ(back.channels, channels);
    EXPECT_EQ(back.pixels, image.pixels);
    ImageFileInfo info = readImageInfo(path);
    EXPECT_EQ(info.bitsPerChannel, 32);
    EXPECT_EQ(info.format, "exr");
  }
}

TEST(ImageIo, ReadsHalfExrWithOffsetDataWindow) {
  TempDir dir;
  std::string path = dir.file("half.exr");
  Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(99, 99)), window(Imath::V2i(10, 20), Imath::V2i(14, 22));
  std::vector<Imf::Rgba> pixels(5 * 3);
  for (int i = 0; i < 15; ++i) pixels[i] = Imf::Rgba(half(i * 0.25f), half(1.5f), half(-2.0f), half(0.5f));
  {
    Imf::RgbaOutputFile file(path.c_str(), display, window, Imf::WRITE_RGBA);
    file.setFrameBuffer(pixels.data() - 10 - 20 * 5, 1, 5);
    file.writePixels(3);
  }
  Image image = readImage(path);
  ASSERT_EQ(image.width, 5);
  ASSERT_EQ(image.height, 3);
  ASSERT_EQ(image.channels, 4);
  EXPECT_FLOAT_EQ(image.at(3, 2, 0), 13 * 0.25f);
  EXPECT_FLOAT_EQ(image.at(3, 2, 1), 1.5f);
  EXPECT_FLOAT_EQ(image.at(3, 2, 2), -2.0f);
  EXPECT_FLOAT_EQ(image.at(3, 2, 3), 0.5f);
  EXPECT_EQ(readImageInfo(path).bitsPerChannel, 16);
}

TEST(ImageIo, GimpPatternRoundTripsAndKnownPatternLoads) {
  TempDir dir;
  for (int channels = 1; channels <= 4; ++channels) {
    Image image = patternWithChannels(13, 11, channels);
    std::string path = dir.file("my pattern.pat");
    writeImage(path, image);
    expectQuantizedEqual(image, readImage(path), 255.0f);
  }
  auto marble = gimpPattern("Stone/marble1.pat");
  TS_REQUIRE_DATA(marble);
  Image image = readImage(*marble);
  EXPECT_EQ(image.width, 128);
  EXPECT_EQ(image.height, 128);
  EXPECT_EQ(image.channels, 1);
}

TEST(ImageIo, EveryInstalledGimpPatternLoads) {
  auto root = gimpPattern("");
  TS_REQUIRE_DATA(root);
  int loaded = 0;
  for (const auto& entry : fs::recursive_directory_iterator(*root)) {
    if (entry.path().extension() != ".pat") continue;
    std::string path = entry.path().string();
    SCOPED_TRACE(path);
    Image image = readImage(path);
    ImageFileInfo info = readImageInfo(path);
    EXPECT_EQ(info.width, image.width);
    EXPECT_EQ(info.height, image.height);
    EXPECT_EQ(info.channels, image.channels);
    EXPECT_GE(image.width, 16);
    EXPECT_LE(image.width, 512);
    EXPECT_GE(image.height, 16);
    EXPECT_LE(image.height, 512);
    EXPECT_GE(image.channels, 1);
    EXPECT_LE(image.channels, 4);
    auto [low, high] = std::minmax_element(image.pixels.begin(), image.pixels.end());
    EXPECT_GE(*low, 0.0f);
    EXPECT_LE(*high, 1.0f);
    EXPECT_GT(*high - *low, 0.05f) << "a flat pattern suggests misread pixels";
    ++loaded;
  }
  EXPECT_GE(loaded, 50);
}

TEST(ImageIo, ClipsOnlyWhenQuantizing) {
  TempDir dir;
  Image image(3, 1, 1);
  image.pixels = {-0.5f, 1.5f, std::nanf("")};
  for (const char* name : {"c.png", "c.tga", "c.pat"}) {
    writeImage(dir.file(name), image);
    EXPECT_EQ(readImage(dir.file(name)).pixels, (std::vector<float>{0.0f, 1.0f, 0.0f})) << name;
  }
  writeImage(dir.file("c16.png"), image, {.bitsPerChannel = 16});
  EXPECT_EQ(readImage(dir.file("c16.png")).pixels, (std::vector<float>{0.0f, 1.0f, 0.0f}));
}

TEST(ImageIo, FormatIsRecognisedByContent) {
  TempDir dir;
  Image image = patternWithChannels(8, 8, 3);
  writeImage(dir.file("a.png"), image);
  fs::rename(dir.file("a.png"), dir.file("actually-png.jpg"));
  expectQuantizedEqual(image, readImage(dir.file("actually-png.jpg")), 255.0f);
  EXPECT_EQ(readImageInfo(dir.file("actually-png.jpg")).format, "png");
}

TEST(ImageIo, WritesAreDeterministic) {
  TempDir dir;
  Image image = patternWithChannels(33, 21, 4, 11);
  for (std::string name : {"a.png", "a.jpg", "a.bmp", "a.tga", "a.exr", "a.pat", "b.png"}) {
    ImageWriteOptions options{.bitsPerChannel = name == "b.png" ? 16 : 8};
    writeImage(dir.file(name), image, options);
    std::string first = readBytes(dir.file(name));
    writeImage(dir.file(name), image, options);
    EXPECT_TRUE(readBytes(dir.file(name)) == first) << name;
  }
}

TEST(ImageIo, MissingEmptyUnknownAndMislabelledFilesAreInputErrors) {
  TempDir dir;
  expectReadError(dir.file("nothing.png"), "does not exist");
  test::writeBytes(dir.file("image.gif"), "GIF89a");
  expectReadError(dir.file("image.gif"), ".png");
  EXPECT_THROW(readImageInfo(dir.file("image.gif")), InputError);
  for (const char* ext : {"png", "jpg", "bmp", "tga", "exr", "pat"}) {
    test::writeBytes(dir.file(std::string("empty.") + ext), "");
    expectReadError(dir.file(std::string("empty.") + ext), "empty");
  }
  test::writeBytes(dir.file("text.png"), "this is just some text, not an image\n");
  expectReadError(dir.file("text.png"), "not a PNG");
  test::writeBytes(dir.file("text.exr"), "this is just some text, not an image\n");
  expectReadError(dir.file("text.exr"), "not a OpenEXR");
  fs::create_directory(dir.file("folder.png"));
  expectReadError(dir.file("folder.png"));
}

TEST(ImageIo, RandomBytesAreInputErrors) {
  TempDir dir;
  for (const char* ext : {"png", "jpg", "bmp", "tga", "exr", "pat"})
    for (int trial = 0; trial < 8; ++trial) {
      Rng rng(hashKey(42, trial));
      std::string bytes(std::size_t(1 + rng.below(3000)), '\0');
      for (char& b : bytes) b = char(rng.below(256));
      // Give some of them a valid signature so the decoders themselves are exercised.
      if (trial % 2 == 1) {
        std::string ext_ = ext;
        if (ext_ == "png") bytes.replace(0, 8, "\x89PNG\r\n\x1a\n");
        if (ext_ == "jpg") bytes.replace(0, 3, "\xff\xd8\xff");
        if (ext_ == "bmp") bytes.replace(0, 2, "BM");
        if (ext_ == "exr") bytes.replace(0, 4, std::string("\x76\x2f\x31\x01", 4));
        if (ext_ == "pat" && bytes.size() >= 24) bytes.replace(20, 4, "GPAT");
      }
      std::string path = dir.file("random" + std::to_string(trial) + "." + ext);
      test::writeBytes(path, bytes);
      expectReadError(path);
    }
}

TEST(ImageIo, TruncatedFilesAreInputErrors) {
  TempDir dir;
  Image image = patternWithChannels(40, 30, 3);
  std::vector<std::string> sources;
  for (const char* name : {"t.png", "t.jpg", "t.bmp", "t.tga", "t.exr", "t.pat"}) {
    writeImage(dir.file(name), image);
    sources.push_back(dir.file(name));
  }
  writeImage(dir.file("t16.png"), image, {.bitsPerChannel = 16});
  sources.push_back(dir.file("t16.png"));
  if (auto real = gimpPattern("Wood/wood1.pat")) sources.push_back(*real);

  for (const std::string& source : sources) {
    std::string bytes = readBytes(source);
    std::size_t n = bytes.size();
    for (std::size_t keep :
         {std::size_t(1), std::size_t(8), std::size_t(20), std::size_t(60), n / 3, n / 2, n * 9 / 10, n - 1}) {
      std::string path = dir.file("cut" + std::to_string(keep) + fs::path(source).filename().string());
      test::writeBytes(path, bytes.substr(0, keep));
      SCOPED_TRACE(source + " cut to " + std::to_string(keep) + " of " + std::to_string(n) + " bytes");
      expectReadError(path);
    }
  }
}

TEST(ImageIo, TruncationMessageSaysWhatIsMissing) {
  TempDir dir;
  writeImage(dir.file("a.pat"), patternWithChannels(256, 256, 3));
  std::string bytes = readBytes(dir.file("a.pat"));
  test::writeBytes(dir.file("a.pat"), bytes.substr(0, bytes.size() - 1000));
  expectReadError(dir.file("a.pat"), "truncated: header says 256x256 RGB but only");
}

// Overwrites a big-endian or little-endian 32-bit field of a file.
void patch32(std::string& bytes, std::size_t at, std::uint32_t v, bool bigEndian) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = char(v >> (bigEndian ? 24 - 8 * i : 8 * i));
}

TEST(ImageIo, AbsurdDeclaredSizesAreRejectedBeforeDecoding) {
  TempDir dir;
  Image image = patternWithChannels(16, 16, 3);
  for (const char* name : {"a.png", "a.bmp", "a.pat", "a.tga", "a.exr"}) writeImage(dir.file(name), image);

  std::string png = readBytes(dir.file("a.png"));
  patch32(png, 16, 100000, true);  // IHDR width, height
  patch32(png, 20, 100000, true);
  test::writeBytes(dir.file("huge.png"), png);
  expectReadError(dir.file("huge.png"));

  patch32(png, 16, 40000, true);  // within 65536 per side but 4.8e9 values
  patch32(png, 20, 40000, true);
  test::writeBytes(dir.file("many.png"), png);
  expectReadError(dir.file("many.png"), "absurd");

  patch32(png, 16, 20000, true);  // plausible numbers, but not from a 1 KB file
  patch32(png, 20, 20000, true);
  test::writeBytes(dir.file("lying.png"), png);
  expectReadError(dir.file("lying.png"), "more than any PNG compression could pack");

  std::string bmp = readBytes(dir.file("a.bmp"));
  patch32(bmp, 18, 100000, false);
  patch32(bmp, 22, 100000, false);
  test::writeBytes(dir.file("huge.bmp"), bmp);
  expectReadError(dir.file("huge.bmp"));

  std::string pat = readBytes(dir.file("a.pat"));
  patch32(pat, 8, 100000, true);
  patch32(pat, 12, 100000, true);
  test::writeBytes(dir.file("huge.pat"), pat);
  expectReadError(dir.file("huge.pat"), "absurd");

  writeImage(dir.file("a.jpg"), image);
  std::string jpg = readBytes(dir.file("a.jpg"));
  std::size_t frame = jpg.find("\xff\xc0");  // baseline frame header: height, width big-endian
  ASSERT_NE(frame, std::string::npos);
  jpg[frame + 5] = jpg[frame + 6] = jpg[frame + 7] = jpg[frame + 8] = char(0xff);
  test::writeBytes(dir.file("huge.jpg"), jpg);
  expectReadError(dir.file("huge.jpg"), "absurd");

  std::string tga = readBytes(dir.file("a.tga"));
  tga[12] = tga[13] = tga[14] = tga[15] = char(0xff);  // 65535 x 65535
  test::writeBytes(dir.file("huge.tga"), tga);
  expectReadError(dir.file("huge.tga"));

  std::string exr = readBytes(dir.file("a.exr"));
  std::size_t window = exr.find(std::string("dataWindow\0box2i\0", 17));
  ASSERT_NE(window, std::string::npos);
  patch32(exr, window + 17 + 4 + 8, 99999, false);  // max.x, max.y after the attribute size
  patch32(exr, window + 17 + 4 + 12, 99999, false);
  test::writeBytes(dir.file("huge.exr"), exr);
  expectReadError(dir.file("huge.exr"));
  EXPECT_THROW(readImageInfo(dir.file("huge.exr")), InputError);
  writeImage(dir.file("b.exr"), patternWithChannels(64, 64, 3));  // big enough to hold the offset table
  exr = readBytes(dir.file("b.exr"));
  window = exr.find(std::string("dataWindow\0box2i\0", 17));
  patch32(exr, window + 17 + 4 + 8, 7999, false);
  patch32(exr, window + 17 + 4 + 12, 7999, false);
  test::writeBytes(dir.file("lying.exr"), exr);
  expectReadError(dir.file("lying.exr"), "more than any OpenEXR compression could pack");
}

// Found by fuzz/fuzz_image: a GIMP pattern's pixels are raw, yet a tiny .pat claiming a large
// image (within the 2^31-value limit) allocated the whole image before finding the file short.
TEST(ImageIo, ShortPatternIsRejectedBeforeAllocating) {
  TempDir dir;
  writeImage(dir.file("a.pat"), patternWithChannels(4, 4, 4));
  std::string pat = readBytes(dir.file("a.pat"));
  patch32(pat, 8, 16384, true);  // 16384 x 16384 RGBA: 4 GiB as floats, from a 100-byte file
  patch32(pat, 12, 16384, true);
  test::writeBytes(dir.file("short.pat"), pat);
  rusage before{}, after{};
  getrusage(RUSAGE_SELF, &before);
  expectReadError(dir.file("short.pat"), "truncated: header says 16384x16384 RGBA but only 64 bytes of pixel data");
  getrusage(RUSAGE_SELF, &after);
  EXPECT_LT(after.ru_maxrss - before.ru_maxrss, 256 * 1024)
      << "peak memory grew by " << after.ru_maxrss - before.ru_maxrss << " KiB";
}

// Found by fuzz/fuzz_image (80 bytes, minimized): an OpenEXR header whose reads seek to an offset
// near 2^64, where MemoryInput's "position + n > size" check wraps around and memcpy reads
// before the buffer. Release builds happen to fail cleanly; the sanitizer build
// (cmake --preset debug) reports the out-of-bounds read until the check is overflow-safe.
TEST(ImageIo, ExrSeekPastTheEndIsAnInputError) {
  const unsigned char bytes[] = {
      0x76, 0x2f, 0x31, 0x01, 0x02, 0x00, 0x00, 0x00, 0x63, 0x68, 0x61, 0x6e, 0x6e, 0x65, 0x6c, 0x73,
      0x00, 0x63, 0x68, 0x6c, 0x69, 0x73, 0x74, 0x00, 0x25, 0x00, 0x00, 0x00, 0x41, 0x00, 0x02, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00,
      0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff,
      0xff, 0xff, 0xff, 0x3d, 0xcd, 0xcc, 0x4c, 0x3f, 0x14, 0xae, 0x07, 0x3f, 0xb8, 0x1e, 0x85, 0x3e,
  };
  TempDir dir;
  test::writeBytes(dir.file("seek.exr"), std::string(reinterpret_cast<const char*>(bytes), sizeof(bytes)));
  expectReadError(dir.file("seek.exr"));
}

// Flipped bytes anywhere in valid files: each read either succeeds with a sane image or
// throws InputError; never a crash, hang, huge allocation or other exception type.
TEST(ImageIo, CorruptedFilesNeverCrash) {
  TempDir dir;
  Image image = patternWithChannels(24, 20, 4);
  for (const char* name : {"f.png", "f.jpg", "f.bmp", "f.tga", "f.exr", "f.pat"}) {
    writeImage(dir.file(name), image);
    std::string original = readBytes(dir.file(name));
    for (int trial = 0; trial < 40; ++trial) {
      Rng rng(hashKey(99, trial, std::hash<std::string>{}(name)));
      std::string bytes = original;
      for (int flips = 1 + int(rng.below(4)); flips > 0; --flips)
        bytes[rng.below(std::uint32_t(bytes.size()))] = char(rng.below(256));
      std::string path = dir.file(std::string("m") + name);
      test::writeBytes(path, bytes);
      try {
        Image back = readImage(path);
        EXPECT_EQ(back.pixels.size(), back.pixelCount() * back.channels);
        EXPECT_LE(back.pixels.size(), std::size_t(1) << 24) << name << " trial " << trial;
      } catch (const InputError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << name << " trial " << trial << ": " << e.what();
      }
    }
  }
}

TEST(ImageIo, BadWriteParametersAreParameterErrorsAndTouchNothing) {
  TempDir dir;
  Image good = patternWithChannels(8, 8, 3);
  std::string path = dir.file("keep.png");
  writeImage(path, good);
  std::string before = readBytes(path);
  EXPECT_THROW(writeImage(dir.file("x.gif"), good), ParameterError);
  EXPECT_THROW(writeImage(path, Image()), ParameterError);
  EXPECT_THROW(writeImage(path, Image(4, 4, 5)), ParameterError);
  EXPECT_THROW(writeImage(path, good, {.bitsPerChannel = 12}), ParameterError);
  EXPECT_THROW(writeImage(path, good, {.jpegQuality = 0}), ParameterError);
  EXPECT_THROW(writeImage(path, good, {.jpegQuality = 101}), ParameterError);
  EXPECT_EQ(readBytes(path), before);
  EXPECT_THROW(writeImage(dir.file("no/such/dir/x.png"), good), OutputError);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

// Makes every file write past `bytes` fail (EFBIG), as a full disk would, while alive.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previousHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previousHandler_);
  }

 private:
  rlimit saved_{};
  void (*previousHandler_)(int) = nullptr;
};

TEST(ImageIo, FailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  TempDir dir;
  Image small = patternWithChannels(4, 4, 3), large = patternWithChannels(256, 256, 4);
  for (const char* name : {"old.png", "old.exr", "old.tga", "old16.png"}) {
    std::string path = dir.file(name);
    ImageWriteOptions options{.bitsPerChannel = std::string(name) == "old16.png" ? 16 : 8};
    writeImage(path, small, options);
    std::string before = readBytes(path);
    {
      FileSizeLimit limit(4096);
      EXPECT_THROW(writeImage(path, large, options), OutputError) << name;
    }
    EXPECT_EQ(readBytes(path), before) << name;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 4)
      << "a temporary file was left";
}

}  // namespace
}  // namespace texsynth
