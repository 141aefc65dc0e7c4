// Welding coincident vertices: a box stored face by face becomes one closed surface; a mesh
// without copies is left exactly as it was.
#include "texsynth/core/mesh_weld.h"

#include <gtest/gtest.h>

using namespace texsynth;

namespace {

// A unit square stored as two triangles with their own corners (6 vertices), plus a lone copy.
Mesh splitSquare() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 1}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  mesh.attributes["uv"] = {2, std::vector<float>(12, 0.5f)};
  mesh.computeNormals();
  return mesh;
}

TEST(MeshWeld, MergesEqualPositionsKeepingTheFirstVertexOfEach) {
  const WeldedMesh welded = weldCoincidentVertices(splitSquare());
  ASSERT_EQ(welded.mesh.vertexCount(), 4u);
  EXPECT_EQ(welded.vertexOf, (std::vector<int>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(welded.mesh.triangles, (std::vector<Vec3i>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(welded.mesh.colors[0], Vec3f(1, 0, 0));  // the first copy's
  EXPECT_TRUE(welded.mesh.attributes.empty());
  ASSERT_EQ(welded.mesh.normals.size(), 4u);
  EXPECT_EQ(welded.mesh.normals[3], Vec3f::UnitZ());
  welded.mesh.validate("welded");
}

TEST(MeshWeld, DropsTrianglesThatCollapse) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 1, 3}};
  const WeldedMesh welded = weldCoincidentVertices(mesh);
  EXPECT_EQ(welded.mesh.triangles, (std::vector<Vec3i>{{0, 1, 2}}));
  EXPECT_EQ(welded.mesh.vertexCount(), 3u);
}

TEST(MeshWeld, AMeshWithoutCopiesComesBackUnchanged) {
  Mesh mesh = splitSquare();
  mesh.positions[3] = {0, 0, 1e-7f};  // no longer exactly the same
  mesh.positions[4] = {1, 1, 1e-7f};
  const WeldedMesh welded = weldCoincidentVertices(mesh);
  EXPECT_EQ(welded.mesh.positions, mesh.positions);
  EXPECT_EQ(welded.mesh.triangles, mesh.triangles);
  EXPECT_EQ(welded.mesh.normals, mesh.normals);
  EXPECT_EQ(welded.mesh.attributes.at("uv").values, mesh.attributes.at("uv").values);
  EXPECT_EQ(welded.vertexOf, (std::vector<int>{0, 1, 2, 3, 4, 5}));
}

}  // namespace
