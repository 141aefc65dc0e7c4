// End-to-end tests of `texsynth surface`: the outputs (colored meshes, render, stats, coordinates,
// a baked texture), --apply-coords, determinism, and one clear error line, the right exit code and
// no output for bad files, bad flags and bad meshes. Small settings: a 48-pixel exemplar, a box of
// 2000 vertices on 2 levels; the exemplar analysis is cached once for the whole file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using test::RunResult;
namespace fs = std::filesystem;

namespace {

const std::string kSmall = " --vertices 2000 --levels 2 --quiet";

// The analysis cache every test shares (the runner gives each test directory its own otherwise).
const test::TempDir& sharedCache() {
  static const test::TempDir dir;
  return dir;
}

RunResult run(const std::string& arguments, const test::TempDir& dir) {
  return test::runTexsynth("surface " + arguments, dir, "TEXSYNTH_CACHE=" + sharedCache().file("cache"));
}

// A box stored face by face with one UV island per face (a 3x2 grid), as an OBJ: the UVs read
// back per vertex and the faces' copies weld into one closed surface.
Mesh uvBox() {
  Mesh box = makeBoxMesh(Vec3f::Zero(), Vec3f::Ones());
  VertexAttribute uv{2, {}};
  for (std::size_t v = 0; v < box.vertexCount(); ++v) {
    const int face = int(v / 4), corner = int(v % 4);
    const float u0 = float(face % 3) / 3.0f, v0 = float(face / 3) / 2.0f;
    uv.values.push_back(u0 + (corner == 1 || corner == 2 ? 0.3f : 0.03f));
    uv.values.push_back(v0 + (corner >= 2 ? 0.45f : 0.05f));
  }
  box.attributes[kUvAttribute] = uv;
  return box;
}

struct Inputs {
  test::TempDir dir;
  std::string exemplar = dir.file("ex.png"), mesh = dir.file("box.obj"), plain = dir.file("box.off");
  Inputs() {
    writeImage(exemplar, test::makeTestPattern(48, 48));
    writeMesh(mesh, uvBox());
    test::writeBytes(plain,
                     "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
                     "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n"
                     "3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n");
  }
  std::string base(const std::string& mesh = "") const {
    return exemplar + " --mesh " + (mesh.empty() ? this->mesh : mesh);
  }
};

// Files in the test directory besides its inputs, `others` and the runner's captures.
std::vector<std::string> outputsIn(const test::TempDir& dir, std::vector<std::string> others = {}) {
  for (const char* name : {"stdout.txt", "stderr.txt", "ex.png", "box.obj", "box.off", "good.ply"})
    others.push_back(name);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    const std::string name = entry.path().filename().string();
    if (std::find(others.begin(), others.end(), name) == others.end()) names.push_back(name);
  }
  return names;
}

}  // namespace

TEST(SurfaceCli, WritesColoredMeshesRenderAndStats) {
  Inputs in;
  const std::string ply = in.dir.file("out.ply"), glb = in.dir.file("out.glb"), stats = in.dir.file("s.json");
  RunResult r = run(in.base() + " -o " + ply + " -o " + glb + " --render " + in.dir.file("r.png") +
                        " --render-size 48 --views 2 --stats " + stats + kSmall,
                    in.dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Mesh out = readMesh(ply);
  EXPECT_GT(out.vertexCount(), 1600u);
  EXPECT_LT(out.vertexCount(), 2400u);
  ASSERT_EQ(out.colors.size(), out.vertexCount());
  EXPECT_NE(*std::min_element(out.colors.begin(), out.colors.end(), [](auto& a, auto& b) { return a.x() < b.x(); }),
            *std::max_element(out.colors.begin(), out.colors.end(), [](auto& a, auto& b) { return a.x() < b.x(); }));
  EXPECT_EQ(readFileBytes(glb).substr(0, 4), "glTF");
  const Image render = readImage(in.dir.file("r.png"));
  EXPECT_EQ(render.width, 96);
  EXPECT_EQ(render.height, 48);

  const nlohmann::json report = nlohmann::json::parse(readFileBytes(stats));
  ASSERT_EQ(report["vertices"].size(), 2u);
  EXPECT_EQ(report["vertices"][1], out.vertexCount());
  EXPECT_LT(report["levels"][0]["vertices"].get<int>(), report["levels"][1]["vertices"].get<int>());
  EXPECT_GT(report["levels"][0]["spacing"].get<double>(), report["levels"][1]["spacing"].get<double>());
  EXPECT_EQ(report["input"]["vertices"], 24);  // the box's faces, welded into one surface of 8
  EXPECT_EQ(report["input"]["welded_vertices"], 8);
  for (const char* stage :
       {"analysis_seconds", "hierarchy_seconds", "prepare_seconds", "synthesis_seconds", "outputs_seconds"})
    EXPECT_GE(report[stage].get<double>(), 0.0) << stage;
  ASSERT_FALSE(report["steps"].empty());
  for (const auto& step : report["steps"]) {
    EXPECT_TRUE(step["neighborhood"] == 17 || step["neighborhood"] == 9) << step;
    EXPECT_GE(step["seconds"].get<double>(), 0.0);
  }
  EXPECT_EQ(report["outputs"].size(), 3u);
  EXPECT_FALSE(report["hierarchy_cached"].get<bool>());
  // The second run on the same mesh finds its hierarchy in the cache.
  r = run(in.base() + " -o " + ply + " --json" + kSmall, in.dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(r.out)["hierarchy_cached"].get<bool>());
}

TEST(SurfaceCli, CoordsThenApplyCoordsReproduceTheColors) {
  Inputs in;
  const std::string coords = in.dir.file("c.ply");
  RunResult r = run(in.base() + " -o " + in.dir.file("a.ply") + " --coords " + coords + kSmall, in.dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const RunResult info = test::runTexsynth("info " + coords + " --json", in.dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out)["vertex_attributes"], nlohmann::json({"source_u", "source_v"}));
  const Mesh stored = readMesh(coords);
  ASSERT_EQ(stored.attributes.count("source_u"), 1u);
  ASSERT_EQ(stored.attributes.count("source_v"), 1u);
  for (float u : stored.attributes.at("source_u").values) {
    ASSERT_GT(u, 0.0f);
    ASSERT_LT(u, 1.0f);
  }
  r = run(in.exemplar + " --apply-coords " + coords + " -o " + in.dir.file("b.ply") + " --quiet", in.dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFileBytes(in.dir.file("b.ply")), readFileBytes(in.dir.file("a.ply")));
  // Another map of the material at twice the resolution (each pixel doubled): the same colors.
  const Image small = readImage(in.exemplar);
  Image large(96, 96, small.channels);
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x)
      for (int c = 0; c < small.channels; ++c) large.at(x, y, c) = small.at(x / 2, y / 2, c);
  writeImage(in.dir.file("large.png"), large);
  r = run(in.dir.file("large.png") + " --apply-coords " + coords + " -o " + in.dir.file("l.ply") + " --quiet", in.dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readMesh(in.dir.file("l.ply")).colors, readMesh(in.dir.file("a.ply")).colors);
}

TEST(SurfaceCli, SameSeedSameBytesForAnyThreadCount) {
  Inputs in;
  auto synthesize = [&](const std::string& name, const std::string& flags) {
    RunResult r = run(in.base() + " -o " + in.dir.file(name) + kSmall + " " + flags, in.dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readFileBytes(in.dir.file(name));
  };
  const std::string one = synthesize("t1.ply", "--threads 1"), two = synthesize("t2.ply", "--threads 2");
  EXPECT_TRUE(one == two) << "--threads 1 and 2 differ";
  EXPECT_TRUE(synthesize("again.ply", "--threads 2") == two);
  EXPECT_FALSE(synthesize("seed.ply", "--seed 7") == one) << "the seed changed nothing";
}

TEST(SurfaceCli, BakesIntoTheUvLayoutOfTheInputMesh) {
  Inputs in;
  const RunResult info = test::runTexsynth("info " + in.mesh + " --json", in.dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_TRUE(nlohmann::json::parse(info.out)["has_uvs"].get<bool>());
  const std::string texture = in.dir.file("t.png");
  RunResult r = run(in.base() + " --bake " + texture + " --bake-size 64" + kSmall, in.dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image baked = readImage(texture);
  ASSERT_EQ(baked.width, 64);
  ASSERT_EQ(baked.height, 64);
  // Inside an island the synthesized texture varies; between the islands' rows (v from 0.45 to
  // 0.55: texel rows 29..34, grown by 2 texels each side) and below the last row lies the one
  // background color.
  bool varies = false;
  for (int x = 3; x < 18; ++x) varies = varies || baked.at(x, 48, 0) != baked.at(3, 48, 0);
  EXPECT_TRUE(varies);
  const float background = baked.at(10, 31, 0);
  EXPECT_EQ(baked.at(40, 32, 0), background);
  EXPECT_EQ(baked.at(10, 63, 0), background);
  // Without UVs, one line naming --bake and the mesh, before any synthesis.
  r = run(in.base(in.plain) + " --bake " + texture + kSmall, in.dir);
  test::expectOneLineError(r, 2, "--bake");
  EXPECT_NE(r.err.find("box.off"), std::string::npos) << r.err;
}

TEST(SurfaceCli, BadFilesAreOneLineExitOneWithNoOutput) {
  Inputs in;
  const std::string out = " -o " + in.dir.file("out.ply") + kSmall;
  test::writeBytes(in.dir.file("good.ply"), "sentinel");
  test::writeBytes(in.dir.file("broken.png"), "not an image");
  writeImage(in.dir.file("tiny.png"), test::makeTestPattern(8, 8));
  test::writeBytes(in.dir.file("nonmanifold.off"),
                   "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  test::writeBytes(in.dir.file("empty.obj"), "");
  test::writeBytes(in.dir.file("flat.off"), "OFF\n3 1 0\n1 1 1\n1 1 1\n1 1 1\n3 0 1 2\n");
  test::writeBytes(in.dir.file("notcoords.ply"), encodePly(makeBoxMesh(Vec3f::Zero(), Vec3f::Ones())));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {in.dir.file("missing.png") + " --mesh " + in.mesh + out, "missing.png"},
      {in.base(in.dir.file("missing.obj")) + out, "missing.obj"},
      {in.dir.file("broken.png") + " --mesh " + in.mesh + out, "broken.png"},
      {in.dir.file("tiny.png") + " --mesh " + in.mesh + out, "tiny.png: a 8x8 exemplar has too few pixels"},
      {in.base(in.dir.file("nonmanifold.off")) + out, "non-manifold edge"},
      {in.base(in.dir.file("empty.obj")) + out, "empty.obj"},
      {in.base(in.dir.file("flat.off")) + out, "flat.off"},
      {in.base(in.dir.file("model.3ds")) + out, "model.3ds"},
      {in.exemplar + " --apply-coords " + in.dir.file("notcoords.ply") + " -o " + in.dir.file("good.ply"),
       "notcoords.ply"},
  };
  for (const auto& [arguments, mention] : cases) {
    SCOPED_TRACE(arguments);
    test::expectOneLineError(run(arguments, in.dir), 1, mention);
    EXPECT_EQ(
        outputsIn(in.dir, {"broken.png", "tiny.png", "nonmanifold.off", "empty.obj", "flat.off", "notcoords.ply"}),
        std::vector<std::string>{});
    EXPECT_FALSE(fs::exists(in.dir.file("out.ply")));
    EXPECT_EQ(readFileBytes(in.dir.file("good.ply")), "sentinel");
  }
  // assimp's malformed models, when installed.
  if (auto invalid = assimpInvalidModels())
    for (const char* name : {"malformed.obj", "malformed2.obj", "empty.off", "empty.ply"}) {
      SCOPED_TRACE(name);
      test::expectOneLineError(run(in.base(*invalid + "/" + name) + out, in.dir), 1, name);
      EXPECT_FALSE(fs::exists(in.dir.file("out.ply")));
    }
}

TEST(SurfaceCli, BadFlagsAreOneLineExitTwoBeforeAnyWork) {
  Inputs in;
  test::writeBytes(in.dir.file("good.ply"), "sentinel");
  const std::string base = in.base(), good = " -o " + in.dir.file("good.ply");
  const std::string sketch = in.dir.file("s.json"), coords = in.dir.file("c.ply");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {base + good + " --vertices 0", "--vertices"},
      {base + good + " --vertices 1e5", "--vertices"},
      {base + good + " --vertices abc", "--vertices"},
      {base + good + " --levels 9", "--levels"},
      {base + good + " --iterations -1", "--iterations"},
      {base + good + " --feature-weight -1", "--feature-weight"},
      {base + good + " --feature-weight nan", "--feature-weight"},
      {base + good + " --up 0,0,0", "--up"},
      {base + good + " --up 1,nan,0", "--up"},
      {base + good + " --up 1,2", "--up"},
      {base + good + " --up 0,0,1 --sketch " + sketch, "--up"},
      {base + good + " --field f.tsfield --sketch " + sketch, "--field"},
      {base + good + " --render-size 64", "--render-size"},
      {base + good + " --views 2", "--views"},
      {base + good + " --bake-size 256", "--bake-size"},
      {base + good + " --render " + in.dir.file("r.ply"), "--render"},
      {base + good + " --bake " + in.dir.file("t.obj"), "--bake"},
      {base + " -o " + in.dir.file("out.png"), "--output"},
      {base + " -o " + in.dir.file("out.stl"), "--output"},
      {base + good + " --coords " + in.dir.file("c.obj"), "--coords"},
      {base, "nothing to write"},
      {in.exemplar + good, "--mesh"},
      {base + " --apply-coords " + coords + good, "--mesh"},
      {in.exemplar + " --apply-coords " + coords + good + " --vertices 100", "--vertices"},
      {in.exemplar + " --apply-coords " + coords + good + " --feature-weight 1", "--feature-weight"},
      {in.exemplar + " --apply-coords " + coords, "--output"},
      {in.exemplar + " --apply-coords " + in.dir.file("c.obj") + good, "--apply-coords"},
      {base + " -o " + in.mesh, "is also an input"},
  };
  for (const auto& [arguments, mention] : cases) {
    SCOPED_TRACE(arguments);
    test::expectOneLineError(run(arguments + " --quiet", in.dir), 2, mention);
    EXPECT_EQ(readFileBytes(in.dir.file("good.ply")), "sentinel");
  }
  EXPECT_EQ(outputsIn(in.dir), std::vector<std::string>{});
  // A destination that cannot be written is a failed output (exit 1), found before any work too.
  test::expectOneLineError(run(base + good + " --stats " + in.dir.file("nodir/s.json"), in.dir), 1, "nodir");
  EXPECT_EQ(readFileBytes(in.dir.file("good.ply")), "sentinel");
}

TEST(SurfaceCli, HelpExplainsDensityOrientationCachingAndGivesAnExample) {
  test::TempDir dir;
  RunResult help = test::runTexsynth("surface --help", dir);
  ASSERT_EQ(help.exitCode, 0);
  for (const char* words : {"one exemplar pixel per vertex spacing", "world +Y", "--up", "cached",
                            "Example:", "--apply-coords", "--bake", "--coords", "--stats", "48000"})
    EXPECT_NE(help.out.find(words), std::string::npos) << words;
}
