// Mesh connectivity: neighbours across edges, fans around vertices in rotation order, borders,
// bow ties, and one clear InputError for each kind of bad mesh.
#include "texsynth/geometry/mesh_topology.h"

#include <gtest/gtest.h>

#include "mesh_test_support.h"
#include "test_support.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

// Every neighbour relation is mutual and joins the same two vertices the other way round.
void expectSymmetricNeighbours(const MeshTopology& topology) {
  const auto& tris = topology.triangles();
  for (int t = 0; t < topology.triangleCount(); ++t)
    for (int e = 0; e < 3; ++e) {
      const int n = topology.neighbor(t, e), ne = topology.neighborEdge(t, e);
      if (n < 0) {
        EXPECT_EQ(ne, -1);
        continue;
      }
      ASSERT_GE(ne, 0);
      EXPECT_EQ(topology.neighbor(n, ne), t);
      EXPECT_EQ(topology.neighborEdge(n, ne), e);
      EXPECT_EQ(tris[n][ne], tris[t][(e + 1) % 3]);
      EXPECT_EQ(tris[n][(ne + 1) % 3], tris[t][e]);
    }
}

// Within a fan, each triangle is the one across the previous one's edge entering v.
void expectFansInRotationOrder(const MeshTopology& topology, int v) {
  for (int k = 0; k < topology.fanCount(v); ++k) {
    const auto fan = topology.fan(v, k);
    ASSERT_FALSE(fan.empty());
    for (std::size_t i = 0; i + 1 < fan.size(); ++i) {
      const int corner = topology.cornerOf(fan[i], v);
      ASSERT_GE(corner, 0);
      EXPECT_EQ(topology.neighbor(fan[i], (corner + 2) % 3), fan[i + 1]) << "vertex " << v << " fan " << k;
    }
  }
}

TEST(MeshTopology, ClosedMeshHasNoBordersAndFullRings) {
  const Mesh sphere = test::icosphere(2);
  const MeshTopology topology(sphere, "icosphere");
  EXPECT_EQ(topology.vertexCount(), 162);
  EXPECT_EQ(topology.triangleCount(), 320);
  EXPECT_TRUE(topology.closed());
  EXPECT_EQ(topology.borderEdgeCount(), 0);
  for (const Vec3f& n : sphere.normals) EXPECT_GT(n.dot(sphere.positions[&n - sphere.normals.data()]), 0.9f);
  expectSymmetricNeighbours(topology);
  std::size_t ringTotal = 0;
  for (int v = 0; v < topology.vertexCount(); ++v) {
    EXPECT_FALSE(topology.isBorderVertex(v));
    EXPECT_EQ(topology.fanCount(v), 1);
    const auto ring = topology.trianglesAround(v);
    EXPECT_TRUE(ring.size() == 5 || ring.size() == 6) << ring.size();
    // A closed fan starts at its lowest triangle and comes back round to it.
    EXPECT_EQ(ring[0], *std::min_element(ring.begin(), ring.end()));
    const int last = ring.back(), corner = topology.cornerOf(last, v);
    EXPECT_EQ(topology.neighbor(last, (corner + 2) % 3), ring[0]);
    expectFansInRotationOrder(topology, v);
    ringTotal += ring.size();
  }
  EXPECT_EQ(ringTotal, 3u * 320u);
}

TEST(MeshTopology, OpenGridHasOneBorderLoop) {
  const int n = 4;
  const MeshTopology topology(test::squareGrid(n), "grid");
  EXPECT_FALSE(topology.closed());
  EXPECT_EQ(topology.borderEdgeCount(), 4 * n);
  expectSymmetricNeighbours(topology);
  int borderVertices = 0;
  for (int v = 0; v < topology.vertexCount(); ++v) {
    const int x = v % (n + 1), y = v / (n + 1);
    const bool onBorder = x == 0 || y == 0 || x == n || y == n;
    EXPECT_EQ(topology.isBorderVertex(v), onBorder) << v;
    borderVertices += topology.isBorderVertex(v);
    EXPECT_EQ(topology.fanCount(v), 1);
    expectFansInRotationOrder(topology, v);
    const auto ring = topology.trianglesAround(v);
    if (!onBorder) {
      EXPECT_EQ(ring.size(), 6u);
    } else {
      // A border fan runs from the triangle whose edge leaving v is on the border to the one
      // whose edge entering v is.
      EXPECT_TRUE(topology.isBorderEdge(ring.front(), topology.cornerOf(ring.front(), v)));
      EXPECT_TRUE(topology.isBorderEdge(ring.back(), (topology.cornerOf(ring.back(), v) + 2) % 3));
    }
  }
  EXPECT_EQ(borderVertices, 4 * n);
}

TEST(MeshTopology, BowTieVertexHasTwoFansAndUnusedVerticesNone) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {5, 5, 5}};
  mesh.triangles = {{0, 1, 2}, {0, 3, 4}};
  const MeshTopology topology(mesh, "bowtie");
  EXPECT_EQ(topology.fanCount(0), 2);
  EXPECT_EQ(topology.fan(0, 0).size(), 1u);
  EXPECT_EQ(topology.fan(0, 0)[0], 0);
  EXPECT_EQ(topology.fan(0, 1)[0], 1);
  EXPECT_EQ(topology.fanCount(5), 0);
  EXPECT_TRUE(topology.trianglesAround(5).empty());
  EXPECT_FALSE(topology.isBorderVertex(5));
  EXPECT_TRUE(topology.isBorderVertex(0));
}

TEST(MeshTopology, RealMeshIsAClosedSurface) {
  const std::optional<Mesh> cow = test::demoMesh("cow.off");
  TS_REQUIRE_DATA(cow);
  const MeshTopology topology(*cow, "cow.off");
  EXPECT_TRUE(topology.closed());
  expectSymmetricNeighbours(topology);
  // Euler characteristic of a sphere: V - E + F = 2.
  EXPECT_EQ(topology.vertexCount() - 3 * topology.triangleCount() / 2 + topology.triangleCount(), 2);
}

TEST(MeshTopology, SameResultForAnyThreadCount) {
  const Mesh sphere = test::icosphere(4);
  const MeshTopology many(sphere, "icosphere");
  ThreadLimit one(1);
  const MeshTopology single(sphere, "icosphere");
  for (int v = 0; v < many.vertexCount(); ++v) {
    const auto a = many.trianglesAround(v), b = single.trianglesAround(v);
    ASSERT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << v;
  }
  for (int t = 0; t < many.triangleCount(); ++t)
    for (int e = 0; e < 3; ++e) ASSERT_EQ(many.neighbor(t, e), single.neighbor(t, e));
}

TEST(MeshTopology, EachBadMeshGivesOneClearInputError) {
  test::expectInputError([] { MeshTopology(Mesh{}, "empty.off"); }, "empty.off", "has no vertices");
  Mesh points;
  points.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  test::expectInputError([&] { MeshTopology(points, "points.off"); }, "points.off", "has no faces");

  Mesh repeated = points;
  repeated.triangles = {{0, 1, 2}, {0, 1, 1}};
  test::expectInputError([&] { MeshTopology(repeated, "a.off"); }, "a.off",
                         "face 1 is degenerate (it repeats a vertex)");

  Mesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  flat.triangles = {{0, 3, 1}, {0, 1, 2}};
  test::expectInputError([&] { MeshTopology(flat, "b.off"); }, "b.off", "face 1 is degenerate (zero area)");

  // Three faces on the edge 0-1 (a "book" of pages).
  Mesh book;
  book.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, -1, 0}};
  book.triangles = {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}};
  test::expectInputError([&] { MeshTopology(book, "c.off"); }, "c.off",
                         "non-manifold edge between vertices 0 and 1 (3 faces)");

  // The second face runs along 0 -> 1 like the first.
  Mesh flipped;
  flipped.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  flipped.triangles = {{0, 1, 2}, {0, 1, 3}};
  test::expectInputError([&] { MeshTopology(flipped, "d.off"); }, "d.off",
                         "faces 0 and 1 traverse the edge between vertices 0 and 1 in the same direction "
                         "(inconsistent orientation)");

  Mesh outOfRange = points;
  outOfRange.triangles = {{0, 1, 7}};
  test::expectInputError([&] { MeshTopology(outOfRange, "e.off"); }, "e.off", "refers to vertex 7");
}

}  // namespace
}  // namespace texsynth
