// Midpoint subdivision: four triangles per triangle, one shared vertex per edge, the same shape.
#include "texsynth/geometry/mesh_subdivision.h"

#include <gtest/gtest.h>

#include <set>

#include "texsynth/core/error.h"
#include "texsynth/render/primitives.h"

namespace texsynth {
namespace {

TEST(MeshSubdivision, OneVertexPerEdgeAndFourTrianglesPerTriangle) {
  Mesh box = makeBoxMesh(Vec3f::Zero(), Vec3f::Ones());
  box.colors.assign(box.positions.size(), Vec3f::Zero());
  box.colors[0] = Vec3f::Ones();
  const Mesh fine = subdivideMidpoint(box);
  std::set<std::pair<int, int>> edges;
  for (const Vec3i& t : box.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  EXPECT_EQ(fine.vertexCount(), box.vertexCount() + edges.size());
  EXPECT_EQ(fine.triangleCount(), box.triangleCount() * 4);
  EXPECT_EQ(fine.bounds().min, box.bounds().min);
  EXPECT_EQ(fine.bounds().max, box.bounds().max);
  EXPECT_NEAR(fine.surfaceArea(), box.surfaceArea(), 1e-5);
  ASSERT_EQ(fine.colors.size(), fine.vertexCount());
  ASSERT_EQ(fine.normals.size(), fine.vertexCount());
  for (std::size_t v = box.vertexCount(); v < fine.vertexCount(); ++v) {
    EXPECT_NEAR(fine.normals[v].norm(), 1.0f, 1e-5f);
    // A midpoint's colour is the mean of its edge's ends: 0 or 1/2 here.
    EXPECT_TRUE(fine.colors[v].x() == 0.0f || fine.colors[v].x() == 0.5f);
  }
  fine.validate("fine");
}

TEST(MeshSubdivision, StopsAtTheVertexBudget) {
  const Mesh box = makeBoxMesh(Vec3f::Zero(), Vec3f::Ones());
  const Mesh dense = subdivideToVertices(box, 1000, 100000);
  EXPECT_GE(dense.vertexCount(), 1000u);
  EXPECT_LT(dense.vertexCount(), 4000u);
  EXPECT_EQ(subdivideToVertices(box, 1000, 20).vertexCount(), box.vertexCount()) << "one level would exceed the cap";
  Mesh broken = box;
  broken.triangles[0][0] = 99;
  EXPECT_THROW(subdivideMidpoint(broken), InputError);
}

}  // namespace
}  // namespace texsynth
