// Volume I/O: NRRD round trips (raw/gzip, float/uint8), hand-made NRRDs of other types and
// byte orders, malformed and truncated files, OpenVDB export re-opened with OpenVDB
// (reading .vdb: volume_vdb_read_test.cpp).
#include "texsynth/io/volume_io.h"

#include <gtest/gtest.h>
#include <openvdb/openvdb.h>
#include <sys/resource.h>
#include <zlib.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/random.h"

namespace texsynth {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

Volume makeVolume(int nx, int ny, int nz, int channels, unsigned seed = 1) {
  Volume volume(nx, ny, nz, channels);
  for (std::size_t i = 0; i < volume.voxels.size(); ++i) volume.voxels[i] = uniform01(hashKey(seed, i));
  return volume;
}

void expectReadError(const std::string& path, const std::string& problem = "") {
  test::expectInputError([&] { readVolume(path); }, path, problem);
}

std::string gzipOf(const std::string& bytes) {
  z_stream s{};
  deflateInit2(&s, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&s, uLong(bytes.size())), '\0');
  s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  s.avail_in = uInt(bytes.size());
  s.next_out = reinterpret_cast<Bytef*>(out.data());
  s.avail_out = uInt(out.size());
  deflate(&s, Z_FINISH);
  out.resize(s.total_out);
  deflateEnd(&s);
  return out;
}

TEST(VolumeIo, NrrdRoundTripsRawAndGzipFloatAndUint8) {
  TempDir dir;
  for (int channels : {1, 3, 4})
    for (bool gzip : {false, true})
      for (bool floatSamples : {true, false}) {
        Volume volume = makeVolume(7, 5, 3, channels, unsigned(channels));
        std::string path = dir.file("v.nrrd");
        writeVolume(path, volume, {.gzip = gzip, .floatSamples = floatSamples});
        Volume back = readVolume(path);
        SCOPED_TRACE("channels " + std::to_string(channels) + " gzip " + std::to_string(gzip) + " float " +
                     std::to_string(floatSamples));
        ASSERT_EQ(back.nx, 7);
        ASSERT_EQ(back.ny, 5);
        ASSERT_EQ(back.nz, 3);
        ASSERT_EQ(back.channels, channels);
        if (floatSamples) {
          EXPECT_EQ(back.voxels, volume.voxels);
        } else {
          for (std::size_t i = 0; i < volume.voxels.size(); ++i)
            ASSERT_NEAR(back.voxels[i], std::round(volume.voxels[i] * 255.0f) / 255.0f, 1e-6f);
        }
        std::string bytes = readFileBytes(path);
        EXPECT_EQ(bytes.rfind("NRRD0004\n", 0), 0u);
        EXPECT_NE(bytes.find(channels == 1 ? "dimension: 3\nsizes: 7 5 3\n"
                                           : "dimension: 4\nsizes: " + std::to_string(channels) + " 7 5 3\n"),
                  std::string::npos);
        std::size_t data = bytes.find("\n\n") + 2;
        if (gzip) {
          EXPECT_EQ(bytes.substr(data, 2), "\x1f\x8b");  // a gzip member, as NRRD tools expect
        }
      }
}

TEST(VolumeIo, NrrdWritesClipUint8AndAreDeterministic) {
  TempDir dir;
  Volume volume(2, 1, 1, 1);
  volume.voxels = {-3.0f, 7.0f};
  writeVolume(dir.file("c.nrrd"), volume, {.floatSamples = false});
  EXPECT_EQ(readVolume(dir.file("c.nrrd")).voxels, (std::vector<float>{0.0f, 1.0f}));

  Volume big = makeVolume(32, 16, 8, 3, 5);
  writeVolume(dir.file("a.nrrd"), big);
  writeVolume(dir.file("b.nrrd"), big);
  EXPECT_EQ(readFileBytes(dir.file("a.nrrd")), readFileBytes(dir.file("b.nrrd")));
}

TEST(VolumeIo, ReadsHandWrittenNrrdsOfOtherTypesAndByteOrders) {
  TempDir dir;
  // Big-endian uint16, with comments, key/value pairs, CRLF line ends and extra fields.
  std::string header =
      "NRRD0005\r\n# a comment\r\ncontent: test\r\ntype: unsigned short\r\ndimension: 3\r\nsizes: 2 1 1\r\n"
      "space dimension: 3\r\nspacings: 1 1 1\r\nmy key:=my value\r\nendian: big\r\nencoding: raw\r\n\r\n";
  test::writeBytes(dir.file("u16.nrrd"), header + std::string("\x00\x00\xff\xff", 4));
  EXPECT_EQ(readVolume(dir.file("u16.nrrd")).voxels, (std::vector<float>{0.0f, 1.0f}));

  // Little-endian int16 in two channels, channel axis first.
  std::int16_t s16[4] = {32767, 0, -32767, 16384};
  test::writeBytes(
      dir.file("s16.nrrd"),
      "NRRD0004\ntype: short\ndimension: 4\nsizes: 2 2 1 1\nkinds: vector domain domain domain\nendian: little\n"
      "encoding: raw\n\n" +
          std::string(reinterpret_cast<const char*>(s16), sizeof(s16)));
  Volume pairs = readVolume(dir.file("s16.nrrd"));
  ASSERT_EQ(pairs.channels, 2);
  ASSERT_EQ(pairs.nx, 2);
  EXPECT_FLOAT_EQ(pairs.at(0, 0, 0, 0), 1.0f);
  EXPECT_FLOAT_EQ(pairs.at(1, 0, 0, 0), -1.0f);
  EXPECT_NEAR(pairs.at(1, 0, 0, 1), 0.5f, 1e-4f);

  // Big-endian double, gzip-encoded by zlib here.
  double values[3] = {0.25, -4.5, 1e3};
  std::string be;
  for (double v : values) {
    char b[8];
    std::memcpy(b, &v, 8);
    for (int i = 7; i >= 0; --i) be.push_back(b[i]);
  }
  test::writeBytes(dir.file("f64.nrrd"),
                   "NRRD0004\ntype: double\ndimension: 3\nsizes: 1 3 1\nendian: big\nencoding: gz\n\n" + gzipOf(be));
  EXPECT_EQ(readVolume(dir.file("f64.nrrd")).voxels, (std::vector<float>{0.25f, -4.5f, 1000.0f}));

  // int8: no endian field needed for one-byte samples.
  test::writeBytes(dir.file("s8.nrrd"), "NRRD0004\ntype: int8\ndimension: 3\nsizes: 1 1 2\nencoding: raw\n\n\x7f\x81");
  EXPECT_EQ(readVolume(dir.file("s8.nrrd")).voxels, (std::vector<float>{1.0f, -1.0f}));
}

TEST(VolumeIo, MalformedNrrdsAreInputErrors) {
  TempDir dir;
  auto write = [&](const std::string& name, const std::string& bytes) {
    test::writeBytes(dir.file(name), bytes);
    return dir.file(name);
  };
  const std::string ok = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n";
  expectReadError(dir.file("missing.nrrd"), "does not exist");
  expectReadError(write("empty.nrrd", ""), "empty");
  expectReadError(write("text.nrrd", "hello world\n"), "not a NRRD");
  expectReadError(write("noend.nrrd", ok), "header never ends");
  expectReadError(write("short.nrrd", ok + "\n" + "abc"),
                  "truncated: header says 2x2x2 uint8 but only 3 bytes of data (need 8)");
  expectReadError(write("huge.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 100000 100000 1\nencoding: raw\n\n"),
                  "absurd");
  expectReadError(write("many.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2048 2048 2048\nencoding: raw\n\n"),
                  "2^31");
  expectReadError(write("zero.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 0 2 2\nencoding: raw\n\n"), "absurd");
  expectReadError(write("count.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2\nencoding: raw\n\n"), "sizes");
  expectReadError(write("dim2.nrrd", "NRRD0004\ntype: uint8\ndimension: 2\nsizes: 2 2\nencoding: raw\n\n"),
                  "dimension 2");
  expectReadError(write("type.nrrd", "NRRD0004\ntype: int64\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\n"), "int64");
  expectReadError(write("notype.nrrd", "NRRD0004\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\n"), "'type'");
  expectReadError(write("enc.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1 1 1\nencoding: bzip2\n\n"), "bzip2");
  expectReadError(write("endian.nrrd", "NRRD0004\ntype: float\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\n1234"),
                  "endian");
  expectReadError(write("number.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 x 2\nencoding: raw\n\n"),
                  "bad number");
  expectReadError(write("line.nrrd", "NRRD0004\ntype uint8\n\n"), "line 2");
  expectReadError(write("detached.nrrd", ok + "data file: other.raw\n\n"), "detached");
  expectReadError(write("skip.nrrd", ok + "byte skip: -1\n\n12345678"), "byte skip");
  expectReadError(write("kinds.nrrd",
                        "NRRD0004\ntype: uint8\ndimension: 4\nsizes: 2 2 2 3\nkinds: domain domain domain RGB-color\n"
                        "encoding: raw\n\n" +
                            std::string(24, 'x')),
                  "channel axis first");
  expectReadError(
      write("bomb.nrrd",
            "NRRD0004\ntype: float\ndimension: 3\nsizes: 1024 1024 512\nendian: little\nencoding: gzip\n\n" +
                gzipOf(std::string(1000, '\0'))),
      "cannot hold");
  const std::string okGzip = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: gzip\n";
  expectReadError(write("badgz.nrrd", okGzip + "\nnot gzip at all"), "corrupt gzip");
  expectReadError(write("shortgz.nrrd", okGzip + "\n" + gzipOf("1234")), "gzip data holds only 4 of the 8 bytes");

  test::writeBytes(dir.file("v.raw"), "whatever");
  expectReadError(dir.file("v.raw"), "(readable: .nrrd .vdb)");
}

// Headers that contradict themselves or their data used to be read anyway (issue 13).
TEST(VolumeIo, InconsistentNrrdsAreInputErrors) {
  TempDir dir;
  auto write = [&](const std::string& name, const std::string& bytes) {
    test::writeBytes(dir.file(name), bytes);
    return dir.file(name);
  };
  const std::string scalar = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\n";
  const std::string eight(8, 'x');
  ASSERT_NO_THROW(readVolume(write("ok.nrrd", scalar + "encoding: raw\n\n" + eight)));
  ASSERT_NO_THROW(readVolume(write("okgz.nrrd", scalar + "encoding: gzip\n\n" + gzipOf(eight))));

  expectReadError(write("trailing.nrrd", scalar + "encoding: raw\n\n" + eight + "zz"), "2 more bytes follow them");
  expectReadError(write("moregz.nrrd", scalar + "encoding: gzip\n\n" + gzipOf(eight + "zz")),
                  "gzip data holds more samples than the header says");
  expectReadError(write("aftergz.nrrd", scalar + "encoding: gzip\n\n" + gzipOf(eight) + "zz"),
                  "2 bytes follow the end of the gzip data");
  expectReadError(write("rgb3d.nrrd", scalar + "kinds: domain domain RGB-color\nencoding: raw\n\n" + eight),
                  "axis 2 is 'RGB-color', but a 3-D NRRD is a scalar volume");
  expectReadError(write("kindcount.nrrd", scalar + "kinds: domain domain\nencoding: raw\n\n" + eight),
                  "'kinds' (line 5) lists 2 axes, but the dimension is 3");
  expectReadError(write("spacings.nrrd", scalar + "spacings: 1 1 1 1\nencoding: raw\n\n" + eight),
                  "'spacings' (line 5) lists 4 axes");
  expectReadError(write("unknownkind.nrrd", scalar + "kinds: domain domain dommain\nencoding: raw\n\n" + eight),
                  "'dommain', an unknown kind");
  expectReadError(write("rgb2.nrrd",
                        "NRRD0004\ntype: uint8\ndimension: 4\nsizes: 2 2 2 1\nkinds: RGB-color domain domain domain\n"
                        "encoding: raw\n\n" +
                            eight),
                  "which has 3 values, but its size is 2");
  expectReadError(write("twice.nrrd", scalar + "encoding: raw\nsizes: 2 2 1\n\n" + eight),
                  "line 6 repeats the field 'sizes' of line 4");
  expectReadError(write("alias.nrrd", scalar + "encoding: raw\nbyte skip: 0\nbyteskip: 0\n\n" + eight), "repeats");
  expectReadError(write("unknown.nrrd", scalar + "encodeing: raw\n\n" + eight), "unknown field 'encodeing'");
  expectReadError(write("number.nrrd", scalar + "number: 9\nencoding: raw\n\n" + eight),
                  "'number: 9' disagrees with sizes 2x2x2 (8 samples)");
  expectReadError(write("magic.nrrd", "NRRD0004 trailing\n" + scalar.substr(9) + "encoding: raw\n\n" + eight),
                  "not a NRRD file");
}

TEST(VolumeIo, TruncatedAndRandomNrrdsAreInputErrors) {
  TempDir dir;
  Volume volume = makeVolume(16, 8, 4, 3);
  for (bool gzip : {false, true}) {
    writeVolume(dir.file("v.nrrd"), volume, {.gzip = gzip});
    std::string bytes = readFileBytes(dir.file("v.nrrd"));
    std::size_t n = bytes.size();
    for (std::size_t keep : {std::size_t(3), std::size_t(30), std::size_t(100), n / 2, n - 5, n - 1}) {
      std::string path = dir.file("cut" + std::to_string(keep) + ".nrrd");
      test::writeBytes(path, bytes.substr(0, keep));
      SCOPED_TRACE("gzip " + std::to_string(gzip) + " cut to " + std::to_string(keep) + " of " + std::to_string(n));
      expectReadError(path);
    }
  }
  for (int trial = 0; trial < 10; ++trial) {
    Rng rng(hashKey(7, trial));
    std::string bytes(std::size_t(rng.below(2000)) + 1, '\0');
    for (char& b : bytes) b = char(rng.below(256));
    if (trial % 2)
      bytes = "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 4 4 4\nendian: little\nencoding: gzip\n\n" + bytes;
    test::writeBytes(dir.file("random.nrrd"), bytes);
    expectReadError(dir.file("random.nrrd"));
  }
}

TEST(VolumeIo, BadWriteRequestsAreParameterErrors) {
  TempDir dir;
  EXPECT_THROW(writeVolume(dir.file("v.raw"), makeVolume(2, 2, 2, 1)), ParameterError);
  EXPECT_THROW(writeVolume(dir.file("v.nrrd"), Volume()), ParameterError);
  EXPECT_THROW(writeVolume(dir.file("v.vdb"), Volume()), ParameterError);
  EXPECT_THROW(writeVolume(dir.file("none/v.nrrd"), makeVolume(2, 2, 2, 1)), OutputError);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(VolumeIo, FailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  TempDir dir;
  std::string nrrd = dir.file("old.nrrd"), vdb = dir.file("old.vdb");
  writeVolume(nrrd, makeVolume(2, 2, 2, 1));
  writeVolume(vdb, makeVolume(2, 2, 2, 1));
  std::string nrrdBefore = readFileBytes(nrrd), vdbBefore = readFileBytes(vdb);
  {
    // Every write past 4 KiB fails (EFBIG), as on a full disk.
    rlimit saved{};
    getrlimit(RLIMIT_FSIZE, &saved);
    auto handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved;
    limit.rlim_cur = 4096;
    setrlimit(RLIMIT_FSIZE, &limit);
    EXPECT_THROW(writeVolume(nrrd, makeVolume(32, 32, 32, 3), {.gzip = false}), OutputError);
    EXPECT_THROW(writeVolume(vdb, makeVolume(32, 32, 32, 3)), OutputError);
    setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, handler);
  }
  EXPECT_EQ(readFileBytes(nrrd), nrrdBefore);
  EXPECT_EQ(readFileBytes(vdb), vdbBefore);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 2)
      << "a temporary file was left";
}

TEST(VolumeIo, VdbHasDensityAndColorGridsInAUnitBox) {
  TempDir dir;
  Volume volume = makeVolume(6, 5, 4, 3, 21);
  volume.at(0, 0, 0, 0) = volume.at(0, 0, 0, 1) = volume.at(0, 0, 0, 2) = 0.0f;  // stays background
  std::string path = dir.file("v.vdb");
  writeVolume(path, volume);

  openvdb::initialize();
  openvdb::io::File file(path);
  file.open();
  auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
  auto color = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("color"));
  file.close();
  ASSERT_TRUE(density);
  ASSERT_TRUE(color);
  EXPECT_NEAR(density->voxelSize()[0], 1.0 / 6.0, 1e-9);
  EXPECT_EQ(density->getGridClass(), openvdb::GRID_FOG_VOLUME);
  auto densityAccess = density->getConstAccessor();
  auto colorAccess = color->getConstAccessor();
  for (auto [x, y, z] : {std::array{1, 2, 3}, std::array{5, 4, 3}, std::array{0, 0, 1}, std::array{3, 0, 2}}) {
    const float* v = volume.voxel(x, y, z);
    openvdb::Coord ijk(x, y, z);
    EXPECT_NEAR(densityAccess.getValue(ijk), 0.2126f * v[0] + 0.7152f * v[1] + 0.0722f * v[2], 1e-6f);
    EXPECT_TRUE(densityAccess.isValueOn(ijk));
    openvdb::Vec3s c = colorAccess.getValue(ijk);
    EXPECT_EQ(c, openvdb::Vec3s(v[0], v[1], v[2]));
  }
  EXPECT_EQ(densityAccess.getValue(openvdb::Coord(0, 0, 0)), 0.0f);
  EXPECT_EQ(densityAccess.getValue(openvdb::Coord(6, 0, 0)), 0.0f);  // outside
  // The volume spans [0,1] along its longest axis.
  openvdb::Vec3d corner = density->transform().indexToWorld(openvdb::Vec3d(-0.5, -0.5, -0.5));
  openvdb::Vec3d far = density->transform().indexToWorld(openvdb::Vec3d(5.5, 4.5, 3.5));
  EXPECT_NEAR(corner.x(), 0.0, 1e-9);
  EXPECT_NEAR(far.x(), 1.0, 1e-9);
}

TEST(VolumeIo, VdbOfAScalarVolumeHasOnlyDensity) {
  TempDir dir;
  Volume volume = makeVolume(3, 3, 3, 1, 4);
  writeVolume(dir.file("s.vdb"), volume);
  openvdb::initialize();
  openvdb::io::File file(dir.file("s.vdb"));
  file.open();
  auto grids = file.getGrids();
  file.close();
  ASSERT_EQ(grids->size(), 1u);
  auto density = openvdb::gridPtrCast<openvdb::FloatGrid>((*grids)[0]);
  ASSERT_TRUE(density);
  EXPECT_EQ(density->getName(), "density");
  EXPECT_EQ(density->getConstAccessor().getValue(openvdb::Coord(2, 1, 0)), volume.at(2, 1, 0, 0));
}

}  // namespace
}  // namespace texsynth
