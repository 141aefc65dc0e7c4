// End-to-end tests of the pixel-based methods of `texsynth image`: optimize, --coords and
// --apply-coords re-applying a synthesis to another map.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "texsynth/io/image_io.h"

using namespace texsynth;
using test::expectOneLineError;
using test::RunResult;
using test::runTexsynth;

namespace {

// The exemplar and a second map of the "same material" (its negative), both 8-bit PNGs.
struct Maps {
  std::string exemplar, other;
  explicit Maps(const test::TempDir& dir) : exemplar(dir.file("exemplar.png")), other(dir.file("other.png")) {
    Image image = test::makeTestPattern(48, 40);
    writeImage(exemplar, image);
    for (float& v : image.pixels) v = 1.0f - v;
    writeImage(other, image);
  }
};

}  // namespace

TEST(PixelSynthesisCli, OptimizeCoordsReapplyToAnotherMap) {
  test::TempDir dir;
  Maps maps(dir);
  for (const char* method : {"optimize", "parallel"}) {
    SCOPED_TRACE(method);
    RunResult r =
        runTexsynth("image " + maps.exemplar + " --method " + method + " --size 52x44 --tileable never --json -o " +
                        dir.file("out.png") + " --coords " + dir.file("coords.exr"),
                    dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    if (std::string(method) == "optimize") {
      nlohmann::json report = nlohmann::json::parse(r.out);
      ASSERT_TRUE(report["iterations"].is_array());
      EXPECT_GT(report["iterations"].size(), 3u);
      EXPECT_LE(report["final_energy"].get<double>(), report["iterations"][0]["energy"].get<double>());
    }
    r = runTexsynth("image " + maps.other + " --apply-coords " + dir.file("coords.exr") +
                        (std::string(method) == "parallel" ? " --seam-blend 0" : "") + " --quiet -o " +
                        dir.file("applied.png"),
                    dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Image out = readImage(dir.file("out.png")), applied = readImage(dir.file("applied.png"));
    ASSERT_EQ(applied.width, 52);
    ASSERT_EQ(applied.height, 44);
    for (std::size_t i = 0; i < out.pixels.size(); ++i)
      ASSERT_NEAR(applied.pixels[i], 1.0f - out.pixels[i], 1.5f / 255) << "sample " << i;  // both maps 8-bit
  }
}

TEST(PixelSynthesisCli, ApplyCoordsRejectsCoordinatesThatDoNotFitTheMap) {
  test::TempDir dir;
  Maps maps(dir);
  ASSERT_EQ(runTexsynth("image " + maps.exemplar + " --method parallel --size 32 --tileable never --quiet -o " +
                            dir.file("out.png") + " --coords " + dir.file("coords.exr"),
                        dir)
                .exitCode,
            0);
  writeImage(dir.file("small.png"), test::makeTestPattern(8, 8));
  expectOneLineError(runTexsynth("image " + dir.file("small.png") + " --apply-coords " + dir.file("coords.exr") +
                                     " -o " + dir.file("x.png"),
                                 dir),
                     1, "coords.exr");
  writeImage(dir.file("gray.exr"), Image(4, 4, 1));
  expectOneLineError(
      runTexsynth("image " + maps.other + " --apply-coords " + dir.file("gray.exr") + " -o " + dir.file("x.png"), dir),
      1, "gray.exr");
  expectOneLineError(
      runTexsynth("image " + maps.other + " --apply-coords " + dir.file("none.exr") + " -o " + dir.file("x.png"), dir),
      1, "none.exr");
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

TEST(PixelSynthesisCli, OptimizeRejectsWhatItCannotDo) {
  test::TempDir dir;
  Maps maps(dir);
  const std::string base = "image " + maps.exemplar + " --method optimize -o " + dir.file("x.png") + " ";
  expectOneLineError(runTexsynth(base + "--window 5,5,32,32", dir), 2, "--window");
  expectOneLineError(runTexsynth(base + "--solver least-squares --coords " + dir.file("c.exr"), dir), 2, "--coords");
  expectOneLineError(runTexsynth(base + "--neighborhood 17,8", dir), 2, "--neighborhood");
  expectOneLineError(runTexsynth(base + "--solver newton", dir), 2, "--solver");
  expectOneLineError(runTexsynth(base + "--iterations 0", dir), 2, "iterations");
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("c.exr")));
}
