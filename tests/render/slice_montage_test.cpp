#include "texsynth/render/slice_montage.h"

#include <gtest/gtest.h>

#include <limits>

#include "texsynth/core/error.h"

using namespace texsynth;

namespace {

// A volume whose every voxel encodes its own coordinates.
Volume coordinateVolume(int nx, int ny, int nz, int channels) {
  Volume volume(nx, ny, nz, channels);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        for (int c = 0; c < channels; ++c)
          volume.at(x, y, z, c) = 0.01f * float(x + 10 * y) + 0.001f * float(z) + 0.1f * float(c);
  return volume;
}

}  // namespace

TEST(SliceMontage, LayoutAndValuesOfScalarVolume) {
  const Volume volume = coordinateVolume(4, 3, 2, 1);
  MontageOptions options;
  options.fractions = {0.0f, 1.0f};
  options.border = 2;
  options.background = Vec3f(0.5f, 0.25f, 0.125f);
  const Image image = sliceMontage(volume, options);
  const int cellWidth = 4, cellHeight = 3;  // max(nx, ny), max(ny, nz)
  ASSERT_EQ(image.channels, 3);
  ASSERT_EQ(image.width, 2 + 2 * (cellWidth + 2));
  ASSERT_EQ(image.height, 2 + 3 * (cellHeight + 2));
  auto origin = [&](int row, int column) { return Vec2i(2 + column * (cellWidth + 2), 2 + row * (cellHeight + 2)); };
  auto expectGray = [&](Vec2i at, float value) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(image.at(at.x(), at.y(), c), value) << at.transpose();
  };
  auto expectBackground = [&](Vec2i at) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(image.at(at.x(), at.y(), c), options.background[c]) << at.transpose();
  };
  // Row 0: x = 0 and x = 3 (fraction 1 is the last voxel); image x follows y, image y follows z.
  for (int column = 0; column < 2; ++column)
    for (int z = 0; z < 2; ++z)
      for (int y = 0; y < 3; ++y) expectGray(origin(0, column) + Vec2i(y, z), volume.at(column * 3, y, z, 0));
  expectBackground(origin(0, 0) + Vec2i(3, 0));  // x-slices are ny = 3 wide in 4-wide cells
  expectBackground(origin(0, 0) + Vec2i(0, 2));  // and nz = 2 tall in 3-tall cells
  // Row 1: y = 0 and y = 2; image (x, z).
  for (int z = 0; z < 2; ++z)
    for (int x = 0; x < 4; ++x) expectGray(origin(1, 1) + Vec2i(x, z), volume.at(x, 2, z, 0));
  // Row 2: z = 0 and z = 1; image (x, y).
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) expectGray(origin(2, 1) + Vec2i(x, y), volume.at(x, y, 1, 0));
  // Borders and corners are background.
  expectBackground({0, 0});
  expectBackground({1, 5});
  expectBackground({image.width - 1, image.height - 1});
  expectBackground(origin(1, 0) - Vec2i(1, 1));
}

TEST(SliceMontage, RgbVolumeScaledUp) {
  const Volume volume = coordinateVolume(3, 3, 3, 4);
  MontageOptions options;
  options.fractions = {0.5f};
  options.border = 0;
  options.scale = 3;
  const Image image = sliceMontage(volume, options);
  ASSERT_EQ(image.width, 9);
  ASSERT_EQ(image.height, 27);
  // Row 2 (z = 1): voxel (x, y) fills pixels [3x, 3x+3) x [18 + 3y, 18 + 3y + 3).
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      for (int dy = 0; dy < 3; ++dy)
        for (int dx = 0; dx < 3; ++dx)
          for (int c = 0; c < 3; ++c) ASSERT_EQ(image.at(3 * x + dx, 18 + 3 * y + dy, c), volume.at(x, y, 1, c));
}

TEST(SliceMontage, BadInputThrows) {
  const Volume volume = coordinateVolume(2, 2, 2, 1);
  auto expectError = [&](const std::string& parameter, const Volume& v, const MontageOptions& options) {
    try {
      sliceMontage(v, options);
      ADD_FAILURE() << "no error for " << parameter;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.parameter(), parameter) << e.what();
    }
  };
  MontageOptions options;
  expectError("volume", Volume(), options);
  expectError("volume", coordinateVolume(2, 2, 2, 2), options);
  options.fractions = {};
  expectError("fractions", volume, options);
  options.fractions = {0.5f, 1.5f};
  expectError("fractions", volume, options);
  options.fractions = {std::numeric_limits<float>::quiet_NaN()};
  expectError("fractions", volume, options);
  options = {};
  options.border = -1;
  expectError("border", volume, options);
  options = {};
  options.scale = 0;
  expectError("scale", volume, options);
}
