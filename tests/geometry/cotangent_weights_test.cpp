// Cotangent edge weights: half the cotangent of each opposite angle, summed over an edge's
// triangles, every edge once in ascending order, degenerate triangles clamped.
#include "texsynth/geometry/cotangent_weights.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsynth {
namespace {

// The unit square split along its diagonal 0-2: two right isosceles triangles.
Mesh unitSquare() {
  Mesh mesh;
  mesh.positions = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0), Vec3f(0, 1, 0)};
  mesh.triangles = {Vec3i(0, 1, 2), Vec3i(0, 2, 3)};
  return mesh;
}

TEST(CotangentWeights, HalfTheOppositeCotangentsOfEveryEdgeOnceInOrder) {
  const std::vector<CotangentEdge> edges = cotangentEdges(unitSquare(), 1e3);
  ASSERT_EQ(edges.size(), 5u);
  const std::pair<int, int> expected[] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {2, 3}};
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_EQ(edges[i].a, expected[i].first);
    EXPECT_EQ(edges[i].b, expected[i].second);
  }
  // The sides face 45-degree corners (cot 1) in one triangle each; the diagonal faces the two
  // right angles (cot 0).
  for (const CotangentEdge& e : edges) EXPECT_NEAR(e.weight, e.b - e.a == 2 ? 0.0 : 0.5, 1e-12) << e.a << "-" << e.b;
}

TEST(CotangentWeights, AnObtuseAngleGivesANegativeWeightAndADegenerateOneIsClamped) {
  Mesh mesh;
  // The corner at vertex 2 is 2 * atan(4) = 152 degrees: cot = -15/8.
  mesh.positions = {Vec3f(-1, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 0.25f, 0)};
  mesh.triangles = {Vec3i(0, 1, 2)};
  const std::vector<CotangentEdge> obtuse = cotangentEdges(mesh, 1e3);
  ASSERT_EQ(obtuse.size(), 3u);
  EXPECT_EQ(obtuse[0].b, 1);
  EXPECT_NEAR(obtuse[0].weight, 0.5 * (-15.0 / 8.0), 1e-6);
  // All three corners on a line: the sine is 0, the weights are half the clamp, of the cosine's sign.
  mesh.positions[2] = Vec3f(0, 0, 0);
  for (const CotangentEdge& e : cotangentEdges(mesh, 100.0)) EXPECT_EQ(std::abs(e.weight), 50.0);
}

}  // namespace
}  // namespace texsynth
