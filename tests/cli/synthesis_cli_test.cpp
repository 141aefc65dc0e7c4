// End-to-end tests of `texsynth image` and `texsynth solid`: windows, outputs, bad parameters.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;

namespace {

// A small exemplar on disk (8-bit, as users give them).
std::string writeExemplar(const test::TempDir& dir) {
  std::string path = dir.file("exemplar.png");
  writeImage(path, test::makeTestPattern(48, 40));
  return path;
}

}  // namespace

TEST(ImageCli, WindowEqualsTheSameRegionOfALargerOutput) {
  test::TempDir dir;
  std::string exemplar = writeExemplar(dir);
  for (const char* method : {"tile-deform", "tile-blend", "parallel"}) {
    SCOPED_TRACE(method);
    std::string common = " --method " + std::string(method) + " --seed 7 --quiet --tileable never";
    ASSERT_EQ(
        runTexsynth("image " + exemplar + " -o " + dir.file("big.png") + " --size 160x120" + common, dir).exitCode, 0);
    RunResult r =
        runTexsynth("image " + exemplar + " -o " + dir.file("win.png") + " --window 37,51,64,40" + common, dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Image big = readImage(dir.file("big.png")), window = readImage(dir.file("win.png"));
    EXPECT_EQ(window.pixels, big.crop(37, 51, 64, 40).pixels);
  }
}

TEST(ImageCli, ParallelWritesSourceCoordinatesThatReproduceTheOutput) {
  test::TempDir dir;
  std::string exemplar = writeExemplar(dir);
  RunResult r = runTexsynth("image " + exemplar + " --method parallel --size 40x24 --quiet --tileable never -o " +
                                dir.file("out.png") + " --coords " + dir.file("coords.exr"),
                            dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  Image source = readImage(exemplar), out = readImage(dir.file("out.png")), coords = readImage(dir.file("coords.exr"));
  ASSERT_EQ(coords.channels, 2);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(out.at(x, y, c), source.at(int(coords.at(x, y, 0)), int(coords.at(x, y, 1)), c)) << x << "," << y;
}

TEST(ImageCli, SeedsDifferAndThreadCountsAgree) {
  test::TempDir dir;
  std::string exemplar = writeExemplar(dir);
  auto run = [&](const std::string& extra, const std::string& name) {
    RunResult r = runTexsynth("image " + exemplar + " -o " + dir.file(name) + " --size 96 --quiet " + extra, dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readFileBytes(dir.file(name));
  };
  EXPECT_EQ(run("--seed 3 --threads 1", "a.png"), run("--seed 3 --threads 2", "b.png"));
  EXPECT_NE(run("--seed 3", "c.png"), run("--seed 4", "d.png"));
}

TEST(ImageCli, NonTileableExemplarIsConvertedAndSaved) {
  test::TempDir dir;
  // A horizontal ramp: its wrap-around edge is a hard seam.
  Image ramp(64, 64, 3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) ramp.at(x, y, c) = x / 63.0f;
  writeImage(dir.file("ramp.png"), ramp);
  RunResult r = runTexsynth("image " + dir.file("ramp.png") + " -o " + dir.file("out.png") + " --size 64 --json" +
                                " --save-tileable " + dir.file("tileable.png"),
                            dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto report = nlohmann::json::parse(r.out);
  EXPECT_TRUE(report["made_tileable"].get<bool>());
  EXPECT_LT(report["seam_ratio_after"].get<double>(), report["seam_ratio_before"].get<double>() / 2);
  EXPECT_TRUE(std::filesystem::exists(dir.file("tileable.png")));
}

TEST(ImageCli, BadParametersAreUsageErrors) {
  test::TempDir dir;
  std::string exemplar = writeExemplar(dir);
  for (const char* bad : {"--lambda -1", "--cell 0,-3", "--lambda abc", "--window 1,2,3", "--window 0,0,0,5",
                          "--method quilting", "--clamp nan"}) {
    SCOPED_TRACE(bad);
    RunResult r = runTexsynth("image " + exemplar + " -o " + dir.file("x.png") + " " + bad, dir);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(test::lineCount(r.err), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

TEST(SolidCli, WritesMeshSlicesVolumeAndRender) {
  test::TempDir dir;
  std::string exemplar = writeExemplar(dir);
  writeMesh(dir.file("ball.ply"), makeUvSphereMesh(Vec3f::Zero(), 1.0f, 12, 24));
  for (const char* method : {"tile-deform", "tile-blend"}) {
    SCOPED_TRACE(method);
    RunResult r = runTexsynth("solid " + exemplar + " --method " + method + " --mesh " + dir.file("ball.ply") + " -o " +
                                  dir.file("ball_colored.ply") + " --slice z=0.5 -o " + dir.file("slice.png") + " -o " +
                                  dir.file("vol.nrrd") + " --resolution 24 --render " + dir.file("view.png") +
                                  " --render-size 64 --quiet --stats " + dir.file("stats.json"),
                              dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Mesh colored = readMesh(dir.file("ball_colored.ply"));
    EXPECT_EQ(colored.colors.size(), colored.vertexCount());
    Volume volume = readVolume(dir.file("vol.nrrd"));
    EXPECT_EQ(std::max({volume.nx, volume.ny, volume.nz}), 24);
    EXPECT_EQ(readImage(dir.file("slice.png")).width, 24);
    EXPECT_EQ(readImage(dir.file("view.png")).height, 64);
    EXPECT_TRUE(std::filesystem::exists(dir.file("stats.json")));
  }
  // --cut adds a third view: the ball cut open, its cap coloured by the solid inside.
  RunResult r = runTexsynth("solid " + exemplar + " --mesh " + dir.file("ball.ply") + " --render " +
                                dir.file("cut.png") + " --render-size 64 --cut x=0.5 --quiet",
                            dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image cut = readImage(dir.file("cut.png"));
  EXPECT_EQ(cut.width, 3 * 64);
  double capVariation = 0;  // the cap is textured, not the flat default colour
  for (int x = 2 * 64 + 24; x < 2 * 64 + 40; ++x) capVariation += std::abs(cut.at(x, 32, 0) - cut.at(x + 1, 32, 0));
  EXPECT_GT(capVariation, 0.05);
}

TEST(SolidCli, LazyFollowsASketchAndTakesFeatureMasks) {
  test::TempDir dir;
  std::string exemplar = writeExemplar(dir);
  writeMesh(dir.file("box.ply"), makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
  test::writeBytes(
      dir.file("sketch.json"),
      R"({"curves": [{"points": [[0.1, 0.2, 1.0], [0.5, 0.5, 1.0], [0.9, 0.6, 1.0]], "tangent_axis": "x"}]})");
  Image mask(48, 40, 1, 0.0f);
  for (int y = 0; y < 40; ++y) mask.at(y % 48, y, 0) = 1.0f;
  writeImage(dir.file("mask.png"), mask);
  const std::string base = "solid " + exemplar +
                           " --method lazy --levels 2 --passes 1 --coarsest-passes 1 --tiles 0.25 " + "--mesh " +
                           dir.file("box.ply") + " --slice z=0.5 --resolution 8 --quiet ";
  const std::string lazy = base + "-o " + dir.file("s.png") + " ";
  RunResult plain = runTexsynth(lazy, dir);
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  const Image identity = readImage(dir.file("s.png"));
  RunResult sketched =
      runTexsynth(lazy + "--sketch " + dir.file("sketch.json") + " --stats " + dir.file("st.json"), dir);
  ASSERT_EQ(sketched.exitCode, 0) << sketched.err;
  EXPECT_NE(readImage(dir.file("s.png")).pixels, identity.pixels);
  EXPECT_EQ(nlohmann::json::parse(readFileBytes(dir.file("st.json")))["sketch"], dir.file("sketch.json"));
  RunResult masked = runTexsynth(lazy + "--mask " + dir.file("mask.png"), dir);
  ASSERT_EQ(masked.exitCode, 0) << masked.err;
  EXPECT_NE(readImage(dir.file("s.png")).pixels, identity.pixels);

  writeImage(dir.file("small.png"), Image(8, 8, 1, 0.0f));
  const std::string out = " -o " + dir.file("x.png");
  // A mask of the wrong size is bad data in that file: an input error naming it.
  test::expectOneLineError(runTexsynth(base + "--mask " + dir.file("small.png") + out, dir), 1, "small.png");
  test::expectOneLineError(
      runTexsynth("solid " + exemplar + " --method lazy --sketch " + dir.file("sketch.json") + " --slice z=0.5" + out,
                  dir),
      2, "--sketch");
  test::expectOneLineError(
      runTexsynth("solid " + exemplar + " --mask " + dir.file("mask.png") + " --slice z=0.5" + out, dir), 2, "--mask");
  test::expectOneLineError(runTexsynth("solid " + exemplar + " --cut z=0.5 --slice z=0.5" + out, dir), 2, "--cut");
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

TEST(SolidCli, OutputsAreCheckedBeforeAnyWork) {
  test::TempDir dir;
  std::string exemplar = writeExemplar(dir);
  // A mesh output without --mesh, an image output without --slice, nothing to write, a bad slice.
  for (const std::string& bad :
       {"-o " + dir.file("m.ply"), "-o " + dir.file("s.png"), std::string(""), "--slice w=0.5 -o " + dir.file("s.png"),
        "--slice z=2 -o " + dir.file("s.png"), "-o " + dir.file("v.txt"), "--stack q -o " + dir.file("v.nrrd")}) {
    SCOPED_TRACE(bad);
    RunResult r = runTexsynth("solid " + exemplar + " " + bad, dir);
    EXPECT_EQ(r.exitCode, 2) << r.err;
  }
  RunResult r = runTexsynth("solid " + dir.file("missing.png") + " -o " + dir.file("v.nrrd"), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("missing.png"), std::string::npos);
}

TEST(SolidCli, LazyWritesASliceAndRejectsWhatItCannotDo) {
  test::TempDir dir;
  std::string exemplar = writeExemplar(dir);
  const std::string lazy =
      "solid " + exemplar + " --method lazy --levels 2 --passes 1 --coarsest-passes 1 --tiles 0.25 ";
  RunResult r = runTexsynth(lazy + "--slice z=0.5 --resolution 12 -o " + dir.file("s.png") + " --stats " +
                                dir.file("stats.json") + " --quiet",
                            dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readImage(dir.file("s.png")).width, 12);
  auto stats = nlohmann::json::parse(readFileBytes(dir.file("stats.json")));
  ASSERT_EQ(stats["lazy"].size(), 1u);
  const auto& finest = stats["lazy"][0]["levels"][1];
  EXPECT_GT(finest["corrections"].get<std::int64_t>(), 0);
  EXPECT_GE(finest["comparisons"].get<std::int64_t>(), finest["corrections"].get<std::int64_t>());
  EXPECT_GE(finest["seconds"].get<double>(), 0.0);
  EXPECT_FALSE(stats["lazy"][0]["levels"][0]["from_disk_cache"].get<bool>());
  // The same command again reads the coarsest level from the disk cache and writes the same slice.
  r = runTexsynth(lazy + "--slice z=0.5 --resolution 12 -o " + dir.file("again.png") + " --stats " +
                      dir.file("again.json") + " --quiet",
                  dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(readFileBytes(dir.file("again.json")))["lazy"][0]["levels"][0]["from_disk_cache"]
                  .get<bool>());
  EXPECT_EQ(readFileBytes(dir.file("again.png")), readFileBytes(dir.file("s.png")));
  const std::string out = " --slice z=0.5 -o " + dir.file("x.png");
  test::expectOneLineError(runTexsynth(lazy + "--candidates 0" + out, dir), 2, "--candidates");
  test::expectOneLineError(runTexsynth(lazy + "--subpasses 3" + out, dir), 2, "--subpasses");
  test::expectOneLineError(runTexsynth(lazy + "--color-rule grey" + out, dir), 2, "--color-rule");
  test::expectOneLineError(runTexsynth(lazy + exemplar + out, dir), 2, "EXEMPLAR");  // two exemplars
  test::expectOneLineError(runTexsynth(lazy + "--inner " + exemplar + out, dir), 2, "--inner");
  test::expectOneLineError(
      runTexsynth("solid " + exemplar + " " + exemplar + " " + exemplar + " --method tile-blend" + out, dir), 2,
      "EXEMPLAR");
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}
