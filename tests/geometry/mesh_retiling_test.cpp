// Retiling: the requested vertex count within 15%, near-uniform edges, borders kept on the
// input's border, the same result every time and for any thread count.
#include "texsynth/geometry/mesh_retiling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh_test_support.h"
#include "test_support.h"
#include "texsynth/core/parallel.h"
#include "texsynth/geometry/mesh_topology.h"

namespace texsynth {
namespace {

struct EdgeStats {
  double mean = 0, spread = 0, low = 0,
         high = 0;  // spread: standard deviation / mean; low, high: 1st, 99th percentile / mean
};

EdgeStats edgeStats(const Mesh& mesh) {
  std::vector<double> lengths;
  for (const Vec3i& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) lengths.push_back((mesh.positions[t[e]] - mesh.positions[t[(e + 1) % 3]]).norm());
  std::sort(lengths.begin(), lengths.end());
  EdgeStats s;
  for (double l : lengths) s.mean += l / double(lengths.size());
  for (double l : lengths) s.spread += (l - s.mean) * (l - s.mean) / double(lengths.size());
  s.spread = std::sqrt(s.spread) / s.mean;
  s.low = lengths[lengths.size() / 100] / s.mean;
  s.high = lengths[lengths.size() * 99 / 100] / s.mean;
  return s;
}

void expectNearUniform(const Mesh& mesh, int target) {
  EXPECT_NEAR(double(mesh.vertexCount()), target, 0.15 * target);
  EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
  const EdgeStats s = edgeStats(mesh);
  EXPECT_LT(s.spread, 0.2);
  EXPECT_GT(s.low, 0.6);
  EXPECT_LT(s.high, 1.45);
  // The regular-triangulation edge length for that many vertices.
  EXPECT_NEAR(s.mean, std::sqrt(2 * mesh.surfaceArea() / (std::sqrt(3.0) * double(mesh.vertexCount()))), 0.1 * s.mean);
}

RetileOptions target(int vertices) {
  RetileOptions options;
  options.targetVertices = vertices;
  return options;
}

TEST(MeshRetiling, ClosedSphereAtTheRequestedCount) {
  const Mesh sphere = test::icosphere(3);  // 642 vertices
  const Mesh retiled = retileMesh(sphere, target(2000), "icosphere");
  expectNearUniform(retiled, 2000);
  EXPECT_TRUE(MeshTopology(retiled, "retiled").closed());
  for (const Vec3f& p : retiled.positions) EXPECT_NEAR(p.norm(), 1.0f, 0.01f);
  for (std::size_t v = 0; v < retiled.positions.size(); ++v)
    EXPECT_GT(retiled.normals[v].dot(retiled.positions[v]), 0.9f);  // still outward
}

TEST(MeshRetiling, OpenGridKeepsItsBorder) {
  const Mesh grid = test::squareGrid(10, 2.0f);
  const Mesh retiled = retileMesh(grid, target(600), "grid");
  expectNearUniform(retiled, 600);
  EXPECT_NEAR(retiled.surfaceArea(), 4.0, 1e-3);
  const MeshTopology topology(retiled, "retiled");
  int border = 0;
  for (int v = 0; v < topology.vertexCount(); ++v) {
    const Vec3f& p = retiled.positions[std::size_t(v)];
    EXPECT_NEAR(p.z(), 0.0f, 1e-6f);
    if (!topology.isBorderVertex(v)) continue;
    ++border;
    const float toEdge = std::min({p.x(), p.y(), 2.0f - p.x(), 2.0f - p.y()});
    EXPECT_NEAR(toEdge, 0.0f, 1e-5f) << p.transpose();
  }
  // Border edges as long as the others: the perimeter over the mean edge length.
  const double expected = 8.0 / edgeStats(retiled).mean;
  EXPECT_NEAR(double(border), expected, 0.25 * expected);
}

TEST(MeshRetiling, RealMeshAtTheRequestedCount) {
  const std::optional<Mesh> cow = test::demoMesh("cow.off");
  TS_REQUIRE_DATA(cow);
  expectNearUniform(retileMesh(*cow, target(4000), "cow.off"), 4000);
}

TEST(MeshRetiling, BowTieVerticesAreSplit) {
  Mesh two = test::squareGrid(4);
  const Mesh other = test::squareGrid(4);
  const int offset = int(two.positions.size());
  for (const Vec3f& p : other.positions) two.positions.push_back(p + Vec3f(1, 1, 0));
  for (const Vec3i& t : other.triangles) two.triangles.push_back(t + Vec3i::Constant(offset));
  // Weld the second square's corner (0, 0) onto the first one's corner (1, 1).
  for (Vec3i& t : two.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] == offset) t[k] = 24;
  two.computeNormals();
  ASSERT_EQ(MeshTopology(two, "bowtie").fanCount(24), 2);
  const Mesh retiled = retileMesh(two, target(300), "bowtie");
  EXPECT_NEAR(double(retiled.vertexCount()), 300, 45);
  EXPECT_NEAR(retiled.surfaceArea(), 2.0, 1e-3);
}

TEST(MeshRetiling, SameResultTwiceAndForAnyThreadCount) {
  const Mesh sphere = test::icosphere(2);
  const Mesh a = retileMesh(sphere, target(1500), "icosphere");
  const Mesh b = retileMesh(sphere, target(1500), "icosphere");
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  ThreadLimit one(1);
  const Mesh c = retileMesh(sphere, target(1500), "icosphere");
  EXPECT_EQ(a.positions, c.positions);
  EXPECT_EQ(a.triangles, c.triangles);
  EXPECT_EQ(a.normals, c.normals);
}

TEST(MeshRetiling, RejectsBadOptionsAndBadMeshes) {
  const Mesh sphere = test::icosphere(1);
  test::expectParameterError([&] { retileMesh(sphere, target(0), "s.off"); }, "targetVertices");
  RetileOptions options = target(100);
  options.iterations = 0;
  test::expectParameterError([&] { retileMesh(sphere, options, "s.off"); }, "iterations");
  options = target(100);
  options.tolerance = 0;
  test::expectParameterError([&] { retileMesh(sphere, options, "s.off"); }, "tolerance");
  Mesh flipped = sphere;
  std::swap(flipped.triangles[3][0], flipped.triangles[3][1]);
  test::expectInputError([&] { retileMesh(flipped, target(100), "flipped.off"); }, "flipped.off",
                         "inconsistent orientation");
}

}  // namespace
}  // namespace texsynth
