// Source coordinates stored on a mesh: exact for the exemplar they came from, the same spot of a
// map at another resolution, and clear errors for meshes that are not coordinate files.
#include "texsynth/surface/surface_coordinates.h"

#include <gtest/gtest.h>

#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"

using namespace texsynth;

namespace {

Mesh triangleWithVertices(int n) {
  Mesh mesh;
  for (int i = 0; i < n; ++i) mesh.positions.emplace_back(float(i), float(i % 2), 0.0f);
  mesh.triangles.emplace_back(0, 1, 2);
  return mesh;
}

TEST(SurfaceCoordinates, ReadBackExactlyThroughPly) {
  const int width = 1000, height = 3;
  Mesh mesh = triangleWithVertices(6);
  const std::vector<std::int32_t> sources = {0, 999, 1000, 1999, 2500, 2999};
  storeSourceCoordinates(mesh, sources, width, height);
  const Mesh read = parsePly(encodePly(mesh), "coords.ply");
  EXPECT_EQ(sourcesFromCoordinates(read, width, height, "coords.ply"), sources);
  EXPECT_FLOAT_EQ(read.attributes.at(kSourceUAttribute).values[1], 999.5f / 1000.0f);
  EXPECT_FLOAT_EQ(read.attributes.at(kSourceVAttribute).values[5], 2.5f / 3.0f);
}

TEST(SurfaceCoordinates, AnotherResolutionReadsTheSameSpot) {
  Mesh mesh = triangleWithVertices(3);
  storeSourceCoordinates(mesh, std::vector<std::int32_t>{0, 5, 15}, 4, 4);  // (0,0) (1,1) (3,3)
  // Twice the size: the centre of pixel (x, y) is the corner of pixels 2x..2x+1: (2x+1, 2y+1).
  EXPECT_EQ(sourcesFromCoordinates(mesh, 8, 8, "c"), (std::vector<std::int32_t>{9, 27, 63}));
  // Half the size: the pixel that covers it.
  EXPECT_EQ(sourcesFromCoordinates(mesh, 2, 2, "c"), (std::vector<std::int32_t>{0, 0, 3}));
}

TEST(SurfaceCoordinates, ErrorsNameTheFileOrTheParameter) {
  Mesh mesh = triangleWithVertices(3);
  test::expectInputError([&] { sourcesFromCoordinates(mesh, 4, 4, "plain.ply"); }, "plain.ply", "source_u");
  test::expectParameterError([&] { storeSourceCoordinates(mesh, std::vector<std::int32_t>{0, 1}, 4, 4); }, "sources");
  test::expectParameterError(
      [&] {
        storeSourceCoordinates(mesh, std::vector<std::int32_t>{0, 1, 16}, 4, 4);
      },
      "sources");
  test::expectParameterError([&] { storeSourceCoordinates(mesh, std::vector<std::int32_t>{0, 1, 2}, 0, 4); }, "width");
  storeSourceCoordinates(mesh, std::vector<std::int32_t>{0, 1, 2}, 4, 4);
  test::expectParameterError([&] { sourcesFromCoordinates(mesh, 4, 0, "c.ply"); }, "height");
  mesh.attributes[kSourceVAttribute].values[1] = 1.5f;
  test::expectInputError([&] { sourcesFromCoordinates(mesh, 4, 4, "c.ply"); }, "c.ply", "outside [0, 1]");
  mesh.attributes[kSourceVAttribute].values[1] = std::nanf("");
  test::expectInputError([&] { sourcesFromCoordinates(mesh, 4, 4, "c.ply"); }, "c.ply", "outside [0, 1]");
}

}  // namespace
