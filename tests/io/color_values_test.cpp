// Float volumes and EXR colour images hold what was stored: NaN, infinities and absurd
// magnitudes (1e30) are refused when read as colours, naming the file and the first bad sample.
#include "texsynth/io/color_values.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_support.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/volume_io.h"

namespace texsynth {
namespace {
using test::TempDir;

// A 4x5x6 float RGB volume of plain colours with voxel (1, 2, 3) channel 2 set to `value`.
Volume volumeHolding(float value) {
  Volume volume(4, 5, 6, 3, 0.5f);
  volume.at(1, 2, 3, 2) = value;
  return volume;
}

void expectRefused(const std::string& path, const std::string& value) {
  test::expectInputError([&] { readVolume(path); }, path, "voxel (1, 2, 3) channel 2 holds " + value);
}

TEST(ColorValues, FloatNrrdWithNonFiniteOrAbsurdValuesIsRefused) {
  TempDir dir;
  const std::pair<float, const char*> cases[] = {{1e30f, "1e+30"},
                                                 {-2e6f, "-2e+06"},
                                                 {std::numeric_limits<float>::quiet_NaN(), "NaN"},
                                                 {std::numeric_limits<float>::infinity(), "infinity"}};
  for (const auto& [value, text] : cases) {
    SCOPED_TRACE(text);
    for (bool gzip : {false, true}) {
      const std::string path = dir.file(gzip ? "bad.gz.nrrd" : "bad.nrrd");
      writeVolume(path, volumeHolding(value), {.gzip = gzip});
      expectRefused(path, text);
    }
  }
}

TEST(ColorValues, FloatVdbWithNonFiniteValuesIsRefused) {
  TempDir dir;
  const std::string path = dir.file("bad.vdb");
  writeVolume(path, volumeHolding(std::numeric_limits<float>::quiet_NaN()));
  expectRefused(path, "NaN");
  writeVolume(path, volumeHolding(-1e30f));
  expectRefused(path, "-1e+30");
}

TEST(ColorValues, HdrAndEightBitScaledFloatsUpToTheLimitAreKept) {
  TempDir dir;
  const std::string path = dir.file("ok.nrrd");
  for (float value : {255.0f, -3.0f, kMaxColorMagnitude, -kMaxColorMagnitude}) {
    writeVolume(path, volumeHolding(value));
    EXPECT_EQ(readVolume(path).at(1, 2, 3, 2), value);
  }
}

TEST(ColorValues, ColorImagesRefuseNonFiniteExrWhileDataImagesKeepIt) {
  TempDir dir;
  const std::string path = dir.file("bad.exr");
  Image image(6, 4, 3, 0.25f);
  image.at(5, 3, 1) = std::numeric_limits<float>::quiet_NaN();
  writeImage(path, image);
  test::expectInputError([&] { readColorImage(path); }, path, "pixel (5, 3) channel 1 holds NaN");
  EXPECT_TRUE(std::isnan(readImage(path).at(5, 3, 1)));  // velocities and coordinates check their own
  image.at(5, 3, 1) = 4e7f;
  writeImage(path, image);
  test::expectInputError([&] { readColorImage(path); }, path, "pixel (5, 3) channel 1 holds 4e+07");
  image.at(5, 3, 1) = 40.0f;  // HDR
  writeImage(path, image);
  EXPECT_EQ(readColorImage(path).at(5, 3, 1), 40.0f);
}

}  // namespace
}  // namespace texsynth
