// End-to-end tests of `texsynth animate`: numbered frames and a GIF from a preset flow, frames
// on a mesh, the same bits for any thread count, and one clear error line with no output for a
// malformed or wrongly sized velocity file, a bad preset and output names without a frame number.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using test::RunResult;
namespace fs = std::filesystem;

namespace {

const test::TempDir& sharedCache() {
  static const test::TempDir dir;
  return dir;
}

RunResult run(const std::string& arguments, const test::TempDir& dir) {
  return test::runTexsynth("animate " + arguments + " --quiet", dir, "TEXSYNTH_CACHE=" + sharedCache().file("cache"));
}

std::string exemplarIn(const test::TempDir& dir) {
  const std::string path = dir.file("exemplar.png");
  writeImage(path, test::makeTestPattern(40, 40));
  return path;
}

bool hasVideoEncoder() {
  return std::system("command -v ffmpeg >/dev/null 2>&1") == 0;
}

TEST(AnimateCli, WritesNumberedFramesAVideoAndStats) {
  test::TempDir dir;
  const std::string exemplar = exemplarIn(dir);
  std::string outputs = " -o " + dir.file("frames/%02d.png");
  if (hasVideoEncoder()) outputs += " -o " + dir.file("anim.gif");
  const RunResult r = run(exemplar + " --flow vortex:strength=1.5 --size 32 --frames 4 --levels 2" + outputs +
                              " --stats " + dir.file("s.json"),
                          dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (int t = 0; t < 4; ++t) {
    const Image frame = readImage(dir.file("frames/0" + std::to_string(t) + ".png"));
    EXPECT_EQ(frame.width, 32);
  }
  EXPECT_FALSE(fs::exists(dir.file("frames/04.png")));
  if (hasVideoEncoder()) {
    EXPECT_GT(fs::file_size(dir.file("anim.gif")), 100u);
  }
  const nlohmann::json stats = nlohmann::json::parse(readFileBytes(dir.file("s.json")));
  EXPECT_EQ(stats["frames"].size(), 4u);
  EXPECT_GT(stats["mean_frame_seconds"].get<double>(), 0.0);
  EXPECT_GE(stats["mean_temporal_change"].get<double>(), 0.0);
}

TEST(AnimateCli, SameBitsForAnyThreadCount) {
  test::TempDir dir;
  const std::string exemplar = exemplarIn(dir);
  for (const std::string threads : {"1", "2"}) {
    const RunResult r = run(exemplar + " --flow source:strength=1 --size 32 --frames 3 --levels 2 --threads " +
                                threads + " -o " + dir.file("t" + threads + "_%d.png"),
                            dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  EXPECT_EQ(readFileBytes(dir.file("t1_2.png")), readFileBytes(dir.file("t2_2.png")));
}

TEST(AnimateCli, AnimatesOnAMeshAndWritesColoredMeshes) {
  test::TempDir dir;
  const std::string exemplar = exemplarIn(dir);
  writeMesh(dir.file("box.ply"), makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
  const RunResult r = run(exemplar + " --mesh " + dir.file("box.ply") +
                              " --vertices 2000 --levels 2 --flow swirl --frames 3 --render-size 64 -o " +
                              dir.file("r%d.png") + " -o " + dir.file("c%d.ply"),
                          dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readImage(dir.file("r2.png")).width, 64);
  const Mesh colored = readMesh(dir.file("c2.ply"));
  EXPECT_EQ(colored.colors.size(), colored.positions.size());
  EXPECT_GT(colored.vertexCount(), 1000u);
}

TEST(AnimateCli, BadFlowsAndOutputsGetOneClearErrorAndWriteNothing) {
  test::TempDir dir;
  const std::string exemplar = exemplarIn(dir);
  const std::string frames = " --size 32 --frames 3 --levels 2 -o " + dir.file("out/%d.png");
  test::writeBytes(dir.file("broken.png"), "not a png at all");
  test::expectOneLineError(run(exemplar + " --flow " + dir.file("broken.png") + frames, dir), 1, "broken.png");
  writeImage(dir.file("small.exr"), Image(16, 16, 3));
  test::expectOneLineError(run(exemplar + " --flow " + dir.file("small.exr") + frames, dir), 1, "small.exr");
  writeImage(dir.file("v0.exr"), Image(32, 32, 3));  // frame 1's file is missing
  test::expectOneLineError(run(exemplar + " --flow " + dir.file("v%d.exr") + frames, dir), 1, "v1.exr");
  test::expectOneLineError(run(exemplar + " --flow vortx" + frames, dir), 2, "--flow");
  test::expectOneLineError(run(exemplar + " --flow vortex:radius=-1" + frames, dir), 2, "--flow");
  test::expectOneLineError(run(exemplar + " --flow vortex --size 30 --frames 2 -o " + dir.file("x%d.png"), dir), 2,
                           "--size");
  test::expectOneLineError(run(exemplar + " --flow vortex --frames 2 -o " + dir.file("plain.png"), dir), 2, "--output");
  test::expectOneLineError(run(exemplar + " --flow vortex --frames 2 -o " + dir.file("a.avi"), dir), 2, "--output");
  test::expectOneLineError(run(exemplar + " --flow vortex --coherence -1 --frames 2 -o " + dir.file("y%d.png"), dir), 2,
                           "--coherence");
  test::expectOneLineError(run(exemplar + " --flow downhill --vertices 2000 --frames 2 -o " + dir.file("z%d.png"), dir),
                           2, "--vertices");
  EXPECT_FALSE(fs::exists(dir.file("out")));
  for (const auto& entry : fs::directory_iterator(dir.path()))
    EXPECT_EQ(entry.path().filename().string().find("%"), std::string::npos) << entry.path();
}

}  // namespace
