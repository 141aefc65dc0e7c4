// End-to-end tests of the texsynth binary: what a user sees (exit codes, one-line errors, files).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_runner.h"
#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
namespace fs = std::filesystem;

using test::lineCount;
using test::RunResult;
using test::runTexsynth;

TEST(Cli, HelpListsSubcommands) {
  test::TempDir dir;
  RunResult r = runTexsynth("--help", dir);
  EXPECT_EQ(r.exitCode, 0);
  for (const char* name : {"demo", "eval", "render", "info", "--seed", "--threads", "--quiet"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name;
  EXPECT_EQ(runTexsynth("eval --help", dir).exitCode, 0);
}

TEST(Cli, BadUsageExitsTwoWithOneLine) {
  test::TempDir dir;
  RunResult r = runTexsynth("frobnicate", dir);
  EXPECT_EQ(r.exitCode, 2);
  r = runTexsynth("", dir);
  EXPECT_EQ(r.exitCode, 2);
  r = runTexsynth("render " + dir.file("x.off") + " -o out.png --size 0x5", dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  r = runTexsynth("info a.png --threads -3", dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
}

TEST(Cli, MissingFileExitsOneNamingIt) {
  test::TempDir dir;
  std::string missing = dir.file("no-such-exemplar.png");
  RunResult r = runTexsynth("info " + missing, dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

TEST(Cli, BrokenImageIsOneClearLine) {
  test::TempDir dir;
  test::writeBytes(dir.file("broken.png"), "\x89PNG\r\n\x1a\nthis is not really a png");
  RunResult r = runTexsynth("info " + dir.file("broken.png"), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("broken.png"), std::string::npos) << r.err;
}

TEST(Cli, InfoDescribesImageAsJson) {
  test::TempDir dir;
  writeImage(dir.file("pattern.png"), test::makeTestPattern(40, 30));
  RunResult r = runTexsynth("info " + dir.file("pattern.png") + " --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"width\": 40"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"height\": 30"), std::string::npos) << r.out;
}

TEST(Cli, InfoReadsOpenVdbVolumes) {
  test::TempDir dir;
  Volume volume(5, 4, 3, 3);  // all black but one voxel: the size still comes back
  volume.at(2, 1, 1, 0) = 1.0f;
  writeVolume(dir.file("v.vdb"), volume);
  RunResult r = runTexsynth("info " + dir.file("v.vdb") + " --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto described = nlohmann::json::parse(r.out);
  EXPECT_EQ(described["kind"], "volume");
  EXPECT_EQ(described["size"], nlohmann::json::array({5, 4, 3}));
  EXPECT_EQ(described["channels"], 3);

  test::writeBytes(dir.file("bad.vdb"), "not a vdb");
  r = runTexsynth("info " + dir.file("bad.vdb"), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("not a readable OpenVDB file"), std::string::npos) << r.err;

  // The codec is a module loaded on first use: without it, one clear line naming the file.
  r = runTexsynth("info " + dir.file("v.vdb"), dir, "TEXSYNTH_VDB_MODULE=" + dir.file("missing.so"));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("v.vdb: OpenVDB support is missing"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("missing.so"), std::string::npos) << r.err;
}

TEST(Cli, EvalOfExemplarAgainstItselfIsPerfect) {
  test::TempDir dir;
  writeImage(dir.file("ex.png"), test::makeTestPattern(48, 48));
  RunResult r = runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("ex.png") + " --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"coherence\": 0.0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"completeness\": 0.0"), std::string::npos) << r.out;
}

TEST(Cli, EvalReportsEveryMetricAndLatticeSeesATiling) {
  test::TempDir dir;
  const Image tile = test::makeTestPattern(40, 40, 3);
  writeImage(dir.file("ex.png"), tile);
  writeImage(dir.file("tiled.png"), tile.tiled(120, 100));
  RunResult r = runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("tiled.png"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string out = "\n" + r.out;
  std::size_t at = 0;  // one line each, in this order
  for (const char* name : {"coherence", "completeness", "histogram", "periodicity", "lattice", "sharpness", "time"}) {
    at = out.find(std::string("\n") + name + " ", at);
    EXPECT_NE(at, std::string::npos) << name << " in\n" << r.out;
  }
  EXPECT_NE(r.out.find("a shifted repeat of the same content scores high"), std::string::npos) << r.out;
  r = runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("tiled.png") + " --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto metrics = nlohmann::json::parse(r.out)["metrics"];
  EXPECT_GT(metrics["lattice"].get<double>(), 0.8) << r.out;
  EXPECT_LE(metrics["lattice"].get<double>(), 1.0) << r.out;
  EXPECT_TRUE(metrics.contains("completeness")) << r.out;
}

TEST(Cli, RenderWritesImageAndFailedRenderKeepsOldFile) {
  test::TempDir dir;
  Mesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  quad.computeNormals();
  writeMesh(dir.file("quad.ply"), quad);
  RunResult r =
      runTexsynth("render " + dir.file("quad.ply") + " -o " + dir.file("view.png") + " --size 64 --quiet", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  Image view = readImage(dir.file("view.png"));
  EXPECT_EQ(view.width, 64);
  std::string before = readFileBytes(dir.file("view.png"));
  test::writeBytes(dir.file("bad.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n");  // truncated
  r = runTexsynth("render " + dir.file("bad.off") + " -o " + dir.file("view.png"), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(readFileBytes(dir.file("view.png")), before);
}

// Views stand a mesh on the floor it was built on (here a pyramid on z = 0, so +Z is up) unless
// --up says otherwise; a zero --up is a usage error.
TEST(Cli, RenderStandsTheMeshUpOrFollowsUp) {
  test::TempDir dir;
  Mesh pyramid;
  pyramid.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 3}};
  pyramid.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  writeMesh(dir.file("pyramid.ply"), pyramid);
  auto render = [&](const std::string& name, const std::string& flags) {
    RunResult r = runTexsynth(
        "render " + dir.file("pyramid.ply") + " -o " + dir.file(name) + " --size 32 " + flags + " --quiet", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readFileBytes(dir.file(name));
  };
  const std::string automatic = render("auto.png", ""), plusZ = render("z.png", "--up 0,0,2"),
                    plusY = render("y.png", "--up 0,1,0");
  EXPECT_EQ(automatic, plusZ);
  EXPECT_NE(automatic, plusY);
  test::expectOneLineError(
      runTexsynth("render " + dir.file("pyramid.ply") + " -o " + dir.file("v.png") + " --up 0,0,0", dir), 2, "--up");
}

TEST(Cli, DemoRunsOnDefaultsAndWritesReport) {
  test::TempDir dir;
  RunResult r = runTexsynth("demo -o " + dir.file("demo") + " --quiet", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"report.md", "report.json", "exemplar.png", "gaussian_stack.png", "mesh.png",
                           "mesh_solid.png", "pixel_synthesis.png", "pixel_seams.png", "gradient_magnified.png",
                           "gradient_edit.png", "gradient_synthesized.png", "gradient_solid.tsgs"})
    EXPECT_TRUE(fs::exists(dir.file(std::string("demo/") + name))) << name;
  std::string report = readFileBytes(dir.file("demo/report.json"));
  EXPECT_NE(report.find("periodicity"), std::string::npos);
  EXPECT_NE(report.find("lattice"), std::string::npos);
  EXPECT_NE(report.find("\"optimize\""), std::string::npos);
  EXPECT_NE(report.find("rms_error_255"), std::string::npos);
  // A second run finds the analysis in the cache.
  r = runTexsynth("demo -o " + dir.file("demo2") + " --quiet --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"cached\": true"), std::string::npos) << r.out;
}

TEST(Cli, DemoFallsBackToBuiltInMeshWithoutData) {
  test::TempDir dir;
  fs::create_directories(dir.file("empty-data"));
  RunResult r = runTexsynth("demo -o " + dir.file("demo") + " --quiet --json --render-size 64", dir,
                            "TEXSYNTH_DATA=" + dir.file("empty-data"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("built-in sphere"), std::string::npos) << r.out;
}

// The demo's determinism, command by command at small sizes (the demo itself runs in
// DemoRunsOnDefaultsAndWritesReport): a real exemplar's analysis and parallel synthesis, a solid
// rendered on a real mesh, vectorization with --optimize, an instant edit and gradient synthesis,
// each at 1 and 2 threads with separate caches, give the same bytes.
TEST(Cli, SameSeedSameBitsForAnyThreadCount) {
  test::TempDir dir;
  const std::string exemplar = gimpPattern("Stone/pink_marble.pat").value_or(dir.file("ex.png"));
  if (!gimpPattern("Stone/pink_marble.pat")) writeImage(exemplar, test::makeTestPattern(48, 48));
  const std::string mesh = cgalMesh("bunny00.off").value_or(dir.file("box.ply"));
  if (!cgalMesh("bunny00.off")) writeMesh(mesh, makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
  test::writeBytes(dir.file("strokes.json"),
                   R"({"color": [0.1, 0.4, 0.6], "strokes": [{"points": [[4, 4, 12], [20, 16, 12]]}]})");
  const std::vector<std::string> outputs = {"p.png", "r.png", "m.ply", "v.nrrd", "o.tsgs", "e.tsgs", "g.tsgs"};
  for (const char* threads : {"1", "2"}) {
    const auto run = [&](const std::string& arguments) {
      const RunResult r = runTexsynth(arguments + " --quiet --threads " + threads, dir,
                                      "TEXSYNTH_CACHE=" + dir.file(std::string("cache") + threads));
      ASSERT_EQ(r.exitCode, 0) << arguments << ": " << r.err;
    };
    const auto out = [&](const std::string& name) { return dir.file(threads + name); };
    run("image " + exemplar + " --method parallel --size 64 -o " + out("p.png"));
    run("solid " + exemplar + " --mesh " + mesh + " --render " + out("r.png") + " --render-size 96 -o " + out("m.ply"));
    run("solid " + exemplar + " -o " + out("v.nrrd") + " --resolution 24");
    run("vectorize " + out("v.nrrd") + " --optimize -o " + out("o.tsgs"));
    run("edit " + out("o.tsgs") + " --strokes " + dir.file("strokes.json") + " -o " + out("e.tsgs"));
    run("solid " + exemplar + " --method gradient -o " + out("g.tsgs") + " --resolution 32");
  }
  for (const std::string& name : outputs)
    EXPECT_EQ(readFileBytes(dir.file("1" + name)), readFileBytes(dir.file("2" + name))) << name;
}

TEST(Cli, EvalAndRenderAcceptVolumes) {
  test::TempDir dir;
  writeImage(dir.file("ex.png"), test::makeTestPattern(24, 24));
  Image exemplar = readImage(dir.file("ex.png"));  // as 8-bit quantized, like the CLI sees it
  // A volume of the exemplar stacked along z: its z-normal slices are the exemplar itself.
  Volume volume(24, 24, 8, 3);
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 24; ++x)
        for (int c = 0; c < 3; ++c) volume.at(x, y, z, c) = exemplar.at(x, y, c);
  writeVolume(dir.file("stack.nrrd"), volume);
  RunResult r = runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("stack.nrrd") + " --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report["z"]["coherence"].get<double>(), 0.0);
  for (const char* axis : {"x", "y", "z", "mean"}) EXPECT_TRUE(report[axis].contains("lattice")) << r.out;
  EXPECT_GT(report["x"]["coherence"].get<double>(), 0.0);
  r = runTexsynth("render " + dir.file("stack.nrrd") + " -o " + dir.file("montage.png"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(readImage(dir.file("montage.png")).width, 3 * 24);
}
