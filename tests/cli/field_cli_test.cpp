// End-to-end tests of `texsynth field`: outputs, the glyph render, and one clear error line for
// bad sketches, missing meshes and bad flags.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "texsynth/core/math.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;

namespace {

const char* kSketch = R"({"curves": [
  {"points": [[0.1, 0.2, 1.0], [0.5, 0.5, 1.0], [0.9, 0.6, 1.0]], "tangent_axis": "x"},
  {"points": [[1.0, 0.1, 0.2], [1.0, 0.8, 0.7]]},
  {"on": "plane", "plane": {"normal": [0, 1, 0]}, "points": [[0.2, 0.5, 0.2], [0.8, 0.5, 0.5]]},
  {"mode": "align", "points": [[0.2, 1.0, 0.2], [0.8, 1.0, 0.8]]}
]})";

struct Files {
  std::string mesh, sketch;
};

Files writeInputs(const test::TempDir& dir, const std::string& sketch = kSketch) {
  Files f{dir.file("cube.ply"), dir.file("sketch.json")};
  writeMesh(f.mesh, makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
  test::writeBytes(f.sketch, sketch);
  return f;
}

}  // namespace

TEST(FieldCli, WritesTheFieldAndAGlyphRender) {
  test::TempDir dir;
  Files in = writeInputs(dir);
  RunResult r = runTexsynth("field " + in.mesh + " --sketch " + in.sketch + " -o " + dir.file("f.tsfield") +
                                " --grid 8 --render " + dir.file("glyphs.png") + " --render-size 96 --json --quiet",
                            dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report["curves"].size(), 4u);
  EXPECT_EQ(report["grid_nodes"][0], 9);
  EXPECT_GT(std::filesystem::file_size(dir.file("f.tsfield")), 9u * 9 * 9 * 16);
  Image glyphs = readImage(dir.file("glyphs.png"));
  EXPECT_EQ(glyphs.width, 2 * 96);  // one surface view and the cut
  EXPECT_EQ(glyphs.height, 96);
  // The field file is what `info`-like tools and later commands read back.
  RunResult again = runTexsynth(
      "field " + in.mesh + " --sketch " + in.sketch + " -o " + dir.file("g.tsfield") + " --grid 8 --quiet", dir);
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(readFileBytes(dir.file("f.tsfield")), readFileBytes(dir.file("g.tsfield")));
  RunResult info = runTexsynth("info " + dir.file("f.tsfield") + " --json", dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  auto described = nlohmann::json::parse(info.out);
  EXPECT_EQ(described["kind"], "rotation field");
  EXPECT_EQ(described["nodes"][0], 9);
  EXPECT_GT(described["rotation_from_identity_degrees"]["max"].get<double>(), 1.0);  // the sketch turned it
}

TEST(FieldCli, BadInputsGiveOneClearLine) {
  test::TempDir dir;
  Files in = writeInputs(dir);
  const std::string out = " -o " + dir.file("f.tsfield");
  test::writeBytes(dir.file("broken.json"), "{\"curves\": [");
  test::expectOneLineError(runTexsynth("field " + in.mesh + " --sketch " + dir.file("broken.json") + out, dir), 1,
                           "broken.json: not valid JSON");
  test::writeBytes(dir.file("far.json"), R"({"curves": [{"points": [[0.5, 0.5, 5], [0.6, 0.5, 5]]}]})");
  test::expectOneLineError(runTexsynth("field " + in.mesh + " --sketch " + dir.file("far.json") + out, dir), 1,
                           "from the mesh surface");
  test::expectOneLineError(runTexsynth("field " + dir.file("missing.ply") + " --sketch " + in.sketch + out, dir), 1,
                           "missing.ply");
  test::expectOneLineError(runTexsynth("field " + in.mesh + " --sketch " + dir.file("none.json") + out, dir), 1,
                           "none.json");
  EXPECT_FALSE(std::filesystem::exists(dir.file("f.tsfield")));
}

TEST(FieldCli, BadFlagsAreUsageErrors) {
  test::TempDir dir;
  Files in = writeInputs(dir);
  const std::string base = "field " + in.mesh + " --sketch " + in.sketch;
  test::expectOneLineError(runTexsynth(base + " -o " + dir.file("f.tsfield") + " --grid 1", dir), 2, "--grid");
  test::expectOneLineError(runTexsynth(base + " -o " + dir.file("f.tsfield") + " --grid abc", dir), 2, "--grid");
  test::expectOneLineError(runTexsynth(base + " -o " + dir.file("f.png"), dir), 2, "--output");
  test::expectOneLineError(runTexsynth(base + " -o " + dir.file("f.tsfield") + " --margin 2", dir), 2, "--margin");
  test::expectOneLineError(
      runTexsynth(base + " -o " + dir.file("f.tsfield") + " --render " + dir.file("g.png") + " --cut w=0.5", dir), 2,
      "--cut");
  RunResult help = runTexsynth("field --help", dir);
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("--sketch"), std::string::npos);
}
