// End-to-end tests of the gradient-solid commands as a user runs them: `vectorize`, `edit`, and `.tsgs` inputs to
// `solid` and `render` (outputs, reports, exit codes and error lines).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "texsynth/gradient/vectorize.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;

namespace {

constexpr int kSide = 24;

// Inputs shared by every test, written once: a 24^3 RGB ball with wavy colours on both sides, its mask, and
// the ball vectorized by the library (so edit/solid/render tests do not pay for a vectorize run).
class GradientCommands : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir();
    Volume ball(kSide, kSide, kSide, 3), mask(kSide, kSide, kSide, 1);
    for (int z = 0; z < kSide; ++z)
      for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
          const float r = std::hypot(float(x) - 11.5f, float(y) - 11.5f, float(z) - 11.5f);
          const bool inside = r < 7.0f;
          mask.at(x, y, z, 0) = inside ? 1.0f : 0.0f;
          float* v = ball.voxel(x, y, z);
          if (inside) {
            v[0] = 0.85f, v[1] = 0.3f + 0.2f * std::sin(0.7f * float(x)),
            v[2] = 0.2f + 0.1f * std::cos(0.5f * float(y));
          } else {
            v[0] = 0.2f + 0.15f * std::sin(0.9f * float(x) + 0.4f * float(z)),
            v[1] = 0.4f + 0.2f * std::cos(0.6f * float(y));
            v[2] = 0.7f;
          }
        }
    VolumeWriteOptions bytes;
    bytes.floatSamples = false;  // 8-bit, as users' volumes are
    writeVolume(volume(), ball, bytes);
    writeVolume(maskFile(), mask, bytes);
    writeGradientSolid(solid(), vectorizeVolume(readVolume(volume()), readVolume(maskFile())));
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }

  static std::string volume() { return dir_->file("ball.nrrd"); }
  static std::string maskFile() { return dir_->file("ball_mask.nrrd"); }
  static std::string solid() { return dir_->file("ball.tsgs"); }
  // Each test's own files, so tests never see each other's outputs.
  std::string file(const std::string& name) const { return own_.file(name); }
  RunResult run(const std::string& arguments) const { return runTexsynth(arguments, own_); }
  static nlohmann::json readJson(const std::string& path) { return nlohmann::json::parse(readFileBytes(path)); }

  // A stroke file with one stroke through the ball's centre at `strength`, with `color` (empty: none).
  std::string strokes(const std::string& name, float strength, const std::string& color) const {
    const std::string path = file(name);
    test::writeBytes(path, "{\"version\": 1," + (color.empty() ? "" : "\"color\": " + color + ",") +
                               "\"strokes\": [{\"points\": [[8, 12, 12], [15, 12, 12]], \"strength\": " +
                               std::to_string(strength) + "}]}");
    return path;
  }

  static test::TempDir* dir_;
  test::TempDir own_;
};

test::TempDir* GradientCommands::dir_ = nullptr;

// --- vectorize ---

TEST_F(GradientCommands, VectorizeWritesASolidAndReportsErrorAndSize) {
  RunResult r = run("vectorize " + volume() + " -o " + file("out.tsgs"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The report is a progress message: stderr, so stdout stays for --json.
  EXPECT_NE(r.err.find("RMS error"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("% of the raw volume"), std::string::npos) << r.err;
  const GradientSolid solid = readGradientSolid(file("out.tsgs"));
  EXPECT_EQ(solid.voxels, Vec3i(kSide, kSide, kSide));
  EXPECT_EQ(solid.spacing, 4);
  EXPECT_EQ(solid.channels, 3);
  EXPECT_FALSE(solid.hasRegions());
  EXPECT_FALSE(solid.hasDetail());
}

TEST_F(GradientCommands, OptimizeLowersTheError) {
  ASSERT_EQ(run("vectorize " + volume() + " -o " + file("fit.tsgs") + " --stats " + file("fit.json")).exitCode, 0);
  RunResult r = run("vectorize " + volume() + " -o " + file("opt.tsgs") + " --optimize --iterations 20 --stats " +
                    file("opt.json"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto fit = readJson(file("fit.json")), opt = readJson(file("opt.json"));
  EXPECT_EQ(fit["optimize"], false);
  EXPECT_EQ(opt["optimize"], true);
  EXPECT_GT(fit["rms_error_255"].get<double>(), 0.0);
  EXPECT_LT(opt["rms_error_255"].get<double>(), fit["rms_error_255"].get<double>());
  EXPECT_EQ(opt["file_bytes"], fit["file_bytes"]);  // same representation, better values
}

TEST_F(GradientCommands, MaskGivesTwoRegions) {
  RunResult r =
      run("vectorize " + volume() + " --mask " + maskFile() + " -o " + file("r.tsgs") + " --stats " + file("r.json"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto stats = readJson(file("r.json"));
  EXPECT_EQ(stats["regions"], true);
  EXPECT_GT(stats["boundary_controls"].get<int>(), 0);
  r = run("info " + file("r.tsgs") + " --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto info = nlohmann::json::parse(r.out);
  EXPECT_EQ(info["regions"], true);
  EXPECT_EQ(info["boundary_controls"], stats["boundary_controls"]);
}

TEST_F(GradientCommands, VectorizeUsageErrors) {
  test::expectOneLineError(run("vectorize " + volume() + " -o " + file("a.tsgs") + " --iterations 5"), 2,
                           "--iterations");
  test::expectOneLineError(run("vectorize " + volume() + " -o " + file("a.png")), 2, "a.png");
  test::expectOneLineError(run("vectorize " + volume() + " -o " + file("a.tsgs") + " --spacing 0"), 2, "--spacing");
  EXPECT_FALSE(std::filesystem::exists(file("a.tsgs")));
  EXPECT_FALSE(std::filesystem::exists(file("a.png")));
}

TEST_F(GradientCommands, VectorizeBadVolumesNameTheFile) {
  test::expectOneLineError(run("vectorize " + file("missing.nrrd") + " -o " + file("a.tsgs")), 1, "missing.nrrd");
  test::writeBytes(file("broken.nrrd"), "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 4 4\nencoding: raw\n\n1234");
  test::expectOneLineError(run("vectorize " + file("broken.nrrd") + " -o " + file("a.tsgs")), 1, "broken.nrrd");
  EXPECT_FALSE(std::filesystem::exists(file("a.tsgs")));
}

// A mask that does not fit the volume is bad input in the mask file (README: checks on a file's data report the
// file, exit 1), whether its size or its channel count is wrong.
TEST_F(GradientCommands, MismatchedMaskNamesTheMaskFile) {
  Volume small(kSide / 2, kSide / 2, kSide / 2, 1, 1.0f);
  writeVolume(file("small_mask.nrrd"), small);
  test::expectOneLineError(
      run("vectorize " + volume() + " --mask " + file("small_mask.nrrd") + " -o " + file("a.tsgs")), 1,
      "small_mask.nrrd: is 12x12x12, the volume 24x24x24");
  test::expectOneLineError(run("vectorize " + volume() + " --mask " + volume() + " -o " + file("a.tsgs")), 1,
                           volume() + ": must have one channel");
  EXPECT_FALSE(std::filesystem::exists(file("a.tsgs")));
}

TEST_F(GradientCommands, FailingRunKeepsAnExistingOutput) {
  test::writeBytes(file("keep.tsgs"), "previous result");
  test::writeBytes(file("broken.nrrd"), "NRRD0004\ntruncated");
  EXPECT_EQ(run("vectorize " + file("broken.nrrd") + " -o " + file("keep.tsgs")).exitCode, 1);
  EXPECT_EQ(run("vectorize " + volume() + " --mask " + volume() + " -o " + file("keep.tsgs")).exitCode, 1);  // RGB mask
  EXPECT_EQ(run("vectorize " + volume() + " --iterations 3 -o " + file("keep.tsgs")).exitCode, 2);
  EXPECT_EQ(readFileBytes(file("keep.tsgs")), "previous result");
}

// --- edit ---

TEST_F(GradientCommands, EditRecoloursTheSolid) {
  RunResult r = run("edit " + solid() + " --strokes " + strokes("s.json", 1.0f, "[0.1, 0.9, 0.1]") + " -o " +
                    file("edited.tsgs") + " --stats " + file("e.json"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("stroke voxels"), std::string::npos) << r.err;
  EXPECT_GT(readJson(file("e.json"))["stroke_voxels"].get<int>(), 0);
  const GradientSolid before = readGradientSolid(solid()), after = readGradientSolid(file("edited.tsgs"));
  EXPECT_NE(before.positive, after.positive);
  // The --color flag overrides the file's colour: a different result.
  r = run("edit " + solid() + " --strokes " + strokes("s.json", 1.0f, "[0.1, 0.9, 0.1]") + " --color '#ff0000' -o " +
          file("red.tsgs"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(readGradientSolid(file("red.tsgs")).positive, after.positive);
}

TEST_F(GradientCommands, ProtectStrokesAloneChangeNothing) {
  RunResult r =
      run("edit " + solid() + " --strokes " + strokes("p.json", 0.0f, "") + " --color 1,0,1 -o " + file("same.tsgs"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const GradientSolid before = readGradientSolid(solid()), after = readGradientSolid(file("same.tsgs"));
  ASSERT_EQ(before.positive.size(), after.positive.size());
  // Written again through 8-bit quantization: equal up to float rounding of the same codes.
  for (std::size_t i = 0; i < before.positive.size(); ++i)
    ASSERT_NEAR(before.positive[i], after.positive[i], 1e-5f) << i;
  ASSERT_EQ(before.negative.size(), after.negative.size());
  for (std::size_t i = 0; i < before.negative.size(); ++i) ASSERT_NEAR(before.negative[i], after.negative[i], 1e-5f);
}

TEST_F(GradientCommands, EditErrors) {
  const std::string good = strokes("s.json", 1.0f, "");
  test::writeBytes(file("bad.json"), "{\"strokes\": [{\"points\": [[1, 2]]}]}");
  test::expectOneLineError(
      run("edit " + solid() + " --strokes " + file("bad.json") + " --color 1,0,0 -o " + file("o.tsgs")), 1, "bad.json");
  test::writeBytes(file("junk.json"), "{\"strokes\": [");
  test::expectOneLineError(
      run("edit " + solid() + " --strokes " + file("junk.json") + " --color 1,0,0 -o " + file("o.tsgs")), 1,
      "junk.json");
  for (const char* color : {"2,0,0", "#12345g", "red", "1,0"}) {
    SCOPED_TRACE(color);
    test::expectOneLineError(
        run("edit " + solid() + " --strokes " + good + " --color '" + color + "' -o " + file("o.tsgs")), 2, "--color");
  }
  // No --color and no "color" in the file: nothing to recolour towards.
  test::expectOneLineError(run("edit " + solid() + " --strokes " + good + " -o " + file("o.tsgs")), 2, "--color");
  test::expectOneLineError(run("edit " + solid() + " --strokes " + good + " --color 1,0,0 -o " + file("o.png")), 2,
                           "--output");
  EXPECT_FALSE(std::filesystem::exists(file("o.tsgs")));
}

// --- solid and render with a .tsgs ---

TEST_F(GradientCommands, SolidMagnifiesSlicesAndWritesVolumes) {
  RunResult r = run("solid " + solid() + " --slice z=0.5 -o " + file("s.png") + " --resolution 64 --volume " +
                    file("v.nrrd") + " --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image slice = readImage(file("s.png"));
  EXPECT_EQ(slice.width, 64);  // more pixels than the solid's 24 voxels
  EXPECT_EQ(slice.height, 64);
  const Volume v = readVolume(file("v.nrrd"));
  EXPECT_EQ(v.nx, 64);
  EXPECT_EQ(v.nz, 64);
  // The ball's centre is the inside colour (red ~0.85), the corner the outside one (blue 0.7).
  EXPECT_NEAR(slice.at(32, 32, 0), 0.85f, 0.1f);
  EXPECT_NEAR(slice.at(1, 1, 2), 0.7f, 0.1f);
}

TEST_F(GradientCommands, SolidRefusesSynthesisFlags) {
  test::expectOneLineError(run("solid " + solid() + " --method tile-deform --slice z=0.5 -o " + file("s.png")), 2,
                           "--method");
  test::expectOneLineError(run("solid " + solid() + " --cell 8 --slice z=0.5 -o " + file("s.png")), 2, "--cell");
  EXPECT_FALSE(std::filesystem::exists(file("s.png")));
}

TEST_F(GradientCommands, SolidRendersAMeshAndRenderMakesAMontage) {
  writeMesh(file("ball.ply"), makeUvSphereMesh(Vec3f::Zero(), 1.0f, 12, 24));
  RunResult r = run("solid " + solid() + " --mesh " + file("ball.ply") + " --render " + file("r.png") +
                    " --render-size 48 --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readImage(file("r.png")).height, 48);
  r = run("render " + solid() + " -o " + file("montage.png"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(readImage(file("montage.png")).width, kSide);
}

TEST_F(GradientCommands, DetailAddsGrainOnlyWhenAsked) {
  ASSERT_EQ(run("vectorize " + volume() + " --detail -o " + file("d.tsgs") + " --quiet").exitCode, 0);
  EXPECT_TRUE(readGradientSolid(file("d.tsgs")).hasDetail());
  for (const char* mode : {"on", "off"})
    ASSERT_EQ(run("solid " + file("d.tsgs") + " --detail " + std::string(mode) + " --slice z=0.5 -o " +
                  file(std::string(mode) + ".png") + " --resolution 48 --quiet")
                  .exitCode,
              0);
  EXPECT_NE(readImage(file("on.png")).pixels, readImage(file("off.png")).pixels);
}

}  // namespace

// --- solid --method gradient: synthesis from an image ---

TEST_F(GradientCommands, SolidSynthesizesAGradientSolidFromAnImage) {
  Image exemplar(48, 48, 3);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x)
      for (int c = 0; c < 3; ++c)
        exemplar.at(x, y, c) = 0.5f + 0.3f * std::sin(0.4f * float(x + 2 * c) + 0.2f * float(y));
  writeImage(file("e.png"), exemplar);
  RunResult r = run("solid " + file("e.png") + " --method gradient --resolution 16 --iterations 1 -o " +
                    file("s.tsgs") + " --slice z=0.5 -o " + file("s.png") + " --stats " + file("s.json"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const GradientSolid solid = readGradientSolid(file("s.tsgs"));
  EXPECT_EQ(solid.voxels, Vec3i(16, 16, 16));
  EXPECT_EQ(readImage(file("s.png")).width, 16);
  const auto stats = readJson(file("s.json"));
  EXPECT_GT(stats["synthesis"]["check_points"].get<int>(), 0);
  // The synthesized solid is an input like any other .tsgs.
  ASSERT_EQ(run("solid " + file("s.tsgs") + " --resolution 8 --slice x=0.5 -o " + file("t.png")).exitCode, 0);
  // Only --method gradient writes one.
  test::expectOneLineError(run("solid " + file("e.png") + " --resolution 8 -o " + file("u.tsgs")), 2, "--output");
  EXPECT_FALSE(std::filesystem::exists(file("u.tsgs")));
}
