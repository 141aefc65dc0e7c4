#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <set>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/hash.h"
#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/progress.h"
#include "texsynth/core/random.h"
#include "texsynth/core/volume.h"

using namespace texsynth;

TEST(Image, WrappedAccessAndBilinear) {
  Image img(4, 2, 1);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) img.at(x, y, 0) = float(x + 10 * y);
  EXPECT_EQ(img.wrapped(-1, 0, 0), 3.0f);
  EXPECT_EQ(img.wrapped(4, 3, 0), 10.0f);
  float v;
  img.sampleBilinearWrapped(1.0f, 0.5f, &v);  // halfway between x=0 and x=1 centers
  EXPECT_FLOAT_EQ(v, 0.5f);
  img.sampleBilinearWrapped(0.0f, 0.5f, &v);  // halfway between x=3 (wrapped) and x=0
  EXPECT_FLOAT_EQ(v, 1.5f);
}

TEST(Image, ChannelConversion) {
  Image rgb(1, 1, 3);
  rgb.at(0, 0, 0) = 1;
  Image gray = rgb.withChannels(1);
  EXPECT_NEAR(gray.at(0, 0, 0), 0.2126f, 1e-6);
  Image rgba = gray.withChannels(4);
  EXPECT_FLOAT_EQ(rgba.at(0, 0, 3), 1.0f);
  EXPECT_FLOAT_EQ(rgba.at(0, 0, 2), gray.at(0, 0, 0));
  EXPECT_THROW(Image(-1, 2, 3), ParameterError);
}

TEST(Volume, TrilinearAtCentersAndWrap) {
  Volume vol(2, 2, 2, 1);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) vol.at(x, y, z, 0) = float(x + 2 * y + 4 * z);
  float v;
  vol.sampleTrilinearWrapped(1.5f, 0.5f, 1.5f, &v);
  EXPECT_FLOAT_EQ(v, 5.0f);
  vol.sampleTrilinearWrapped(1.0f, 1.0f, 1.0f, &v);  // the center: mean of all eight
  EXPECT_FLOAT_EQ(v, 3.5f);
}

TEST(Mesh, NormalsAreOutwardOnATetrahedron) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  m.computeNormals();
  Vec3f c = m.bounds().center();
  for (std::size_t i = 0; i < m.vertexCount(); ++i)
    EXPECT_GT(m.normals[i].dot(m.positions[i] - Vec3f(0.25f, 0.25f, 0.25f)), 0);
  EXPECT_NEAR(c.x(), 0.5f, 1e-6);
  m.validate("tetra");
  m.triangles.push_back({0, 1, 7});
  EXPECT_THROW(m.validate("tetra"), InputError);
}

TEST(Frame, QuaternionRoundTripAndNormalFrame) {
  Quatf q(Eigen::AngleAxisf(0.7f, Vec3f(1, 2, 3).normalized()));
  Frame f = Frame::fromQuaternion(q);
  EXPECT_NEAR(std::abs(f.toQuaternion().dot(q)), 1.0f, 1e-5);
  for (Vec3f n : {Vec3f(0, 0, 1), Vec3f(0, 0, -1), Vec3f(1, 2, -3).normalized()}) {
    Frame g = Frame::fromNormal(n);
    EXPECT_NEAR(g.x.dot(g.y), 0, 1e-5);
    EXPECT_NEAR(g.x.cross(g.y).dot(n), 1, 1e-5);
  }
}

TEST(Random, KeysSeparateEveryComponentAndAreUniform) {
  std::set<std::uint64_t> keys;
  for (int s = 0; s < 3; ++s)
    for (int e = 0; e < 3; ++e)
      for (int l = 0; l < 3; ++l)
        for (int p = 0; p < 3; ++p) keys.insert(hashKey(s, e, l, p));
  EXPECT_EQ(keys.size(), 81u);
  double sum = 0;
  int buckets[10] = {};
  for (int i = 0; i < 100000; ++i) {
    float u = uniform01(hashKey(7, i));
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    sum += u;
    buckets[int(u * 10)]++;
  }
  EXPECT_NEAR(sum / 100000, 0.5, 0.01);
  for (int b : buckets) EXPECT_NEAR(b, 10000, 500);
  EXPECT_LT(uniformBelow(hashKey(1, 2), 5), 5u);
}

TEST(Hash, ContentSensitive) {
  Hasher a, b, c;
  a.string("marble").value(3);
  b.string("marble").value(3);
  c.string("marble").value(4);
  EXPECT_EQ(a.digest(), b.digest());
  EXPECT_NE(a.digest(), c.digest());
  EXPECT_EQ(a.hex().size(), 16u);
}

TEST(Parallel, SameResultForAnyThreadCount) {
  auto run = [](int threads) {
    ThreadLimit limit(threads);
    std::vector<float> out(100000);
    parallelFor(
        0, out.size(), [&](std::int64_t i) { out[i] = uniform01(hashKey(3, i)); }, 64);
    return out;
  };
  EXPECT_EQ(run(1), run(2));
  EXPECT_EQ(run(1), run(0));
  EXPECT_THROW(ThreadLimit(-2), ParameterError);
}

TEST(Progress, CancelThrowsFromAdvance) {
  NullProgress p;
  p.begin("work", 10);
  p.advance(1);
  p.cancel();
  EXPECT_THROW(p.advance(1), Cancelled);
}

TEST(AtomicFile, FailedWriteLeavesOldFileIntact) {
  test::TempDir dir;
  std::string path = dir.file("out.txt");
  writeFileAtomically(path, "good");
  EXPECT_THROW(writeAtomically(path,
                               [](const std::string& temp) {
                                 test::writeBytes(temp, "half");
                                 throw OutputError(temp, "simulated failure");
                               }),
               OutputError);
  EXPECT_EQ(readFileBytes(path), "good");
  int files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir.path())) (void)e, ++files;
  EXPECT_EQ(files, 1);  // no temp file left behind
  EXPECT_THROW(writeFileAtomically(dir.file("missing/out.txt"), "x"), OutputError);
  EXPECT_THROW(readFileBytes(dir.file("nope")), InputError);
  EXPECT_EQ(fileExtension("a/b.PNG"), "png");
}

TEST(Image, CropAndTiling) {
  Image img = test::makeTestPattern(10, 8);
  Image window = img.crop(3, 2, 4, 5);
  EXPECT_EQ(window.width, 4);
  EXPECT_EQ(window.at(1, 1, 2), img.at(4, 3, 2));
  EXPECT_THROW(img.crop(8, 0, 4, 4), ParameterError);
  Image tiled = window.tiled(9, 11);
  EXPECT_EQ(tiled.at(8, 10, 0), window.at(0, 0, 0));
  EXPECT_EQ(tiled.at(5, 7, 1), window.at(1, 2, 1));
}
