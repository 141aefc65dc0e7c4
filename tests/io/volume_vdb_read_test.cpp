// Reading OpenVDB volumes: exact round trips through writeVolume (black borders included),
// files written by OpenVDB directly (no size metadata, double and other grid types), and
// truncated, garbage or unusable files as InputErrors.
#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/random.h"
#include "texsynth/io/volume_io.h"

namespace texsynth {
namespace {
using test::TempDir;

// Random voxels in (0,1) inside a border of zeros (which the writer leaves inactive).
Volume blackBorderedVolume(int nx, int ny, int nz, int channels, unsigned seed) {
  Volume volume(nx, ny, nz, channels);
  for (int z = 1; z + 1 < nz; ++z)
    for (int y = 1; y + 1 < ny; ++y)
      for (int x = 1; x + 1 < nx; ++x)
        for (int c = 0; c < channels; ++c)
          volume.at(x, y, z, c) = 0.01f + uniform01(hashKey(seed, volume.voxels.size() + std::size_t(c)));
  return volume;
}

void writeGrids(const std::string& path, const openvdb::GridPtrVec& grids) {
  openvdb::initialize();
  openvdb::io::File(path).write(grids);
}

void expectReadError(const std::string& path, const std::string& problem = "") {
  test::expectInputError([&] { readVolume(path); }, path, problem);
}

TEST(VolumeVdbRead, RoundTripsScalarAndColorVolumesWithBlackBorders) {
  TempDir dir;
  for (int channels : {1, 3}) {
    Volume volume = blackBorderedVolume(7, 5, 4, channels, unsigned(channels));
    std::string path = dir.file("v.vdb");
    writeVolume(path, volume);
    Volume back = readVolume(path);
    SCOPED_TRACE("channels " + std::to_string(channels));
    ASSERT_EQ(back.nx, 7);
    ASSERT_EQ(back.ny, 5);
    ASSERT_EQ(back.nz, 4);
    ASSERT_EQ(back.channels, channels);
    EXPECT_EQ(back.voxels, volume.voxels);
  }
  // All black: only the size metadata says how big it was.
  writeVolume(dir.file("black.vdb"), Volume(3, 2, 1, 1));
  Volume black = readVolume(dir.file("black.vdb"));
  EXPECT_EQ(black.nx * black.ny * black.nz, 6);
  EXPECT_EQ(black.voxels, std::vector<float>(6, 0.0f));
}

TEST(VolumeVdbRead, FourChannelVolumesComeBackAsTheirColor) {
  TempDir dir;
  Volume volume = blackBorderedVolume(4, 4, 4, 4, 9);
  writeVolume(dir.file("rgba.vdb"), volume);
  Volume back = readVolume(dir.file("rgba.vdb"));
  ASSERT_EQ(back.channels, 3);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(back.at(1, 2, 2, c), volume.at(1, 2, 2, c));
}

TEST(VolumeVdbRead, GridsWithoutSizeMetadataUseTheirActiveBox) {
  TempDir dir;
  // A double grid from index 2..3 along x: widened to start at 0, converted to float.
  auto positive = openvdb::DoubleGrid::create(0.0);
  positive->setName("smoke");
  positive->tree().setValue(openvdb::Coord(2, 0, 1), 0.5);
  positive->tree().setValue(openvdb::Coord(3, 1, 0), 0.25);
  writeGrids(dir.file("positive.vdb"), {positive});
  Volume a = readVolume(dir.file("positive.vdb"));
  ASSERT_EQ(a.channels, 1);
  ASSERT_EQ(a.nx, 4);
  ASSERT_EQ(a.ny, 2);
  ASSERT_EQ(a.nz, 2);
  EXPECT_EQ(a.at(2, 0, 1, 0), 0.5f);
  EXPECT_EQ(a.at(3, 1, 0, 0), 0.25f);
  EXPECT_EQ(a.at(0, 0, 0, 0), 0.0f);

  // Negative indices: the active box itself; "density" is preferred over an earlier float grid.
  auto other = openvdb::FloatGrid::create(0.0f);
  other->setName("temperature");
  other->tree().setValue(openvdb::Coord(0), 9.0f);
  auto density = openvdb::FloatGrid::create(0.0f);
  density->setName("density");
  density->tree().setValue(openvdb::Coord(-3, 5, 0), 1.0f);
  density->tree().setValue(openvdb::Coord(-2, 5, 2), 2.0f);
  writeGrids(dir.file("negative.vdb"), {other, density});
  Volume b = readVolume(dir.file("negative.vdb"));
  ASSERT_EQ(b.nx, 2);
  ASSERT_EQ(b.ny, 1);
  ASSERT_EQ(b.nz, 3);
  EXPECT_EQ(b.at(0, 0, 0, 0), 1.0f);
  EXPECT_EQ(b.at(1, 0, 2, 0), 2.0f);
}

TEST(VolumeVdbRead, TruncatedAndGarbageFilesAreInputErrors) {
  TempDir dir;
  writeVolume(dir.file("v.vdb"), blackBorderedVolume(16, 8, 4, 3, 2));
  std::string bytes = readFileBytes(dir.file("v.vdb"));
  std::size_t n = bytes.size();
  for (std::size_t keep : {std::size_t(3), std::size_t(40), std::size_t(200), n / 2, n - 5, n - 1}) {
    std::string path = dir.file("cut" + std::to_string(keep) + ".vdb");
    test::writeBytes(path, bytes.substr(0, keep));
    SCOPED_TRACE("cut to " + std::to_string(keep) + " of " + std::to_string(n));
    expectReadError(path, "not a readable OpenVDB file");
  }
  test::writeBytes(dir.file("text.vdb"), "this is not a volume at all\n");
  expectReadError(dir.file("text.vdb"), "not a readable OpenVDB file");
  for (int trial = 0; trial < 5; ++trial) {
    Rng rng(hashKey(11, trial));
    std::string random(std::size_t(rng.below(2000)) + 1, '\0');
    for (char& b : random) b = char(rng.below(256));
    test::writeBytes(dir.file("random.vdb"), random);
    expectReadError(dir.file("random.vdb"));
  }
  test::writeBytes(dir.file("empty.vdb"), "");
  expectReadError(dir.file("empty.vdb"), "empty");
}

TEST(VolumeVdbRead, UnusableGridsAreInputErrors) {
  TempDir dir;
  auto labels = openvdb::Int32Grid::create(0);
  labels->setName("labels");
  labels->tree().setValue(openvdb::Coord(1), 7);
  writeGrids(dir.file("int.vdb"), {labels});
  expectReadError(dir.file("int.vdb"), "the file holds 'labels' (int32)");

  writeGrids(dir.file("none.vdb"), {});
  expectReadError(dir.file("none.vdb"), "holds no grids");

  auto empty = openvdb::FloatGrid::create(0.0f);
  empty->setName("density");
  writeGrids(dir.file("inactive.vdb"), {empty});
  expectReadError(dir.file("inactive.vdb"), "no active voxels");

  auto wide = openvdb::FloatGrid::create(0.0f);
  wide->tree().setValue(openvdb::Coord(0), 1.0f);
  wide->tree().setValue(openvdb::Coord(100000, 0, 0), 1.0f);
  writeGrids(dir.file("wide.vdb"), {wide});
  expectReadError(dir.file("wide.vdb"), "each side must be 1..65536");

  auto many = openvdb::FloatGrid::create(0.0f);
  many->tree().setValue(openvdb::Coord(0), 1.0f);
  many->tree().setValue(openvdb::Coord(2000, 2000, 2000), 1.0f);
  writeGrids(dir.file("many.vdb"), {many});
  expectReadError(dir.file("many.vdb"), "2^31");
}

}  // namespace
}  // namespace texsynth
