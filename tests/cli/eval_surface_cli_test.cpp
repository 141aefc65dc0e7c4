// `texsynth eval EXEMPLAR MESH`: the surface measures of a mesh with vertex colors (.ply, .obj,
// .glb), one clear error for a mesh without them, mesh-only and image-only flags kept apart.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "test_support.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/random.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {

using test::RunResult;
using test::runTexsynth;

// A flat n x n grid (unit spacing, z = 0), each vertex colored by the exemplar pixel under it,
// exemplar x along +x and exemplar y down along -y (the default orientation on a +z face).
Mesh coloredGrid(const Image& exemplar, int n) {
  Mesh mesh;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) {
      mesh.positions.push_back({float(x), float(y), 0});
      const float* p = exemplar.pixel(x, n - y);
      mesh.colors.push_back({p[0], p[1], p[2]});
    }
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int v = y * (n + 1) + x;
      mesh.triangles.push_back({v, v + 1, v + n + 2});
      mesh.triangles.push_back({v, v + n + 2, v + n + 1});
    }
  mesh.computeNormals();
  return mesh;
}

TEST(EvalSurfaceCli, ReportsSurfaceMeasuresOfAColoredMesh) {
  test::TempDir dir;
  writeImage(dir.file("ex.png"), test::makeTestPattern(48, 48));
  const Image exemplar = readImage(dir.file("ex.png"));
  const Mesh grid = coloredGrid(exemplar, 40);
  // The same grid colored by random exemplar pixels: no texture at all.
  Mesh noise = grid;
  for (std::size_t v = 0; v < noise.vertexCount(); ++v) {
    const float* p = exemplar.pixel(int(uniformBelow(hashKey(5, v, 0), 48)), int(uniformBelow(hashKey(5, v, 1), 48)));
    noise.colors[v] = {p[0], p[1], p[2]};
  }
  writeMesh(dir.file("noise.ply"), noise);
  RunResult r = runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("noise.ply") + " --json --samples 0", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const double random = nlohmann::json::parse(r.out)["surface"]["coherence"].get<double>();
  for (const char* name : {"grid.ply", "grid.obj", "grid.glb"}) {
    SCOPED_TRACE(name);
    writeMesh(dir.file(name), grid);
    r = runTexsynth("eval " + dir.file("ex.png") + " " + dir.file(name) + " --json --samples 0", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto report = nlohmann::json::parse(r.out)["surface"];
    // Each vertex is an exemplar pixel: near 0 (not 0: the spacing sqrt(area / vertices) is 0.976
    // of the grid's, so cells fall between vertices) and far below the random colors.
    EXPECT_LT(report["coherence"].get<double>(), 0.3 * random) << r.out;
    EXPECT_LE(report["rotation_invariant"].get<double>(), report["coherence"].get<double>());
    EXPECT_GT(report["evaluated"].get<int>(), 0);
    EXPECT_GT(report["near_border"].get<int>(), 0);  // the grid's border strip
  }
  RunResult table = runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("grid.ply"), dir);
  ASSERT_EQ(table.exitCode, 0) << table.err;
  EXPECT_NE(table.out.find("rotation-invariant"), std::string::npos) << table.out;
}

TEST(EvalSurfaceCli, MeshWithoutColorsAndMisplacedFlagsAreOneLineErrors) {
  test::TempDir dir;
  writeImage(dir.file("ex.png"), test::makeTestPattern(32, 32));
  Mesh grid = coloredGrid(readImage(dir.file("ex.png")), 20);
  grid.colors.clear();
  writeMesh(dir.file("plain.ply"), grid);
  test::expectOneLineError(runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("plain.ply"), dir), 1,
                           "has no vertex colors");
  test::expectOneLineError(runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("ex.png") + " --samples 10", dir),
                           2, "--samples");
  test::expectOneLineError(
      runTexsynth("eval " + dir.file("ex.png") + " " + dir.file("plain.ply") + " --periodicity-samples 10", dir), 2,
      "--periodicity-samples");
}

}  // namespace
}  // namespace texsynth
