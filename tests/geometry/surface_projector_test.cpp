// Closest points: the triangle and barycentric weights they come with reproduce the point.
#include "texsynth/geometry/surface_projector.h"

#include <gtest/gtest.h>

#include "mesh_test_support.h"

namespace texsynth {
namespace {

Vec3f interpolate(const Mesh& mesh, const SurfacePoint& s) {
  const Vec3i& t = mesh.triangles[std::size_t(s.triangle)];
  return s.barycentric[0] * mesh.positions[t[0]] + s.barycentric[1] * mesh.positions[t[1]] +
         s.barycentric[2] * mesh.positions[t[2]];
}

TEST(SurfaceProjector, ClosestPointComesWithItsTriangleAndWeights) {
  const Mesh grid = test::squareGrid(4);
  const SurfaceProjector projector(grid);
  // Above the grid: straight down, inside a triangle.
  SurfacePoint above = projector.closestPoint(Vec3f(0.3f, 0.6f, 0.5f));
  ASSERT_GE(above.triangle, 0);
  ASSERT_LT(above.triangle, int(grid.triangles.size()));
  EXPECT_NEAR((above.position - Vec3f(0.3f, 0.6f, 0)).norm(), 0, 1e-6f);
  EXPECT_NEAR(above.distance, 0.5f, 1e-6f);
  EXPECT_NEAR(above.barycentric.sum(), 1, 1e-6f);
  EXPECT_GE(above.barycentric.minCoeff(), 0);
  EXPECT_NEAR((interpolate(grid, above) - above.position).norm(), 0, 1e-6f);
  // Beyond the border: onto an edge, so one weight is zero.
  SurfacePoint outside = projector.closestPoint(Vec3f(1.5f, 0.4f, 0));
  ASSERT_GE(outside.triangle, 0);
  EXPECT_NEAR((outside.position - Vec3f(1, 0.4f, 0)).norm(), 0, 1e-6f);
  EXPECT_EQ((outside.barycentric.array() == 0).count(), 1);
  EXPECT_NEAR((interpolate(grid, outside) - outside.position).norm(), 0, 1e-6f);
}

TEST(SurfaceProjector, WeightsAreValidEverywhereOnASphere) {
  const Mesh sphere = test::icosphere(2);
  const SurfaceProjector projector(sphere);
  for (int i = 0; i < 200; ++i) {
    const float a = 0.7f * float(i), b = 0.31f * float(i);
    const Vec3f p =
        (1.0f + 0.2f * std::sin(float(i))) * Vec3f(std::cos(a) * std::cos(b), std::sin(b), std::sin(a) * std::cos(b));
    const SurfacePoint s = projector.closestPoint(p);
    ASSERT_GE(s.triangle, 0);
    EXPECT_GE(s.barycentric.minCoeff(), 0);
    EXPECT_NEAR(s.barycentric.sum(), 1, 1e-5f);
    EXPECT_NEAR((interpolate(sphere, s) - s.position).norm(), 0, 1e-5f);
    EXPECT_NEAR((s.position - p).norm(), s.distance, 1e-5f);
  }
}

}  // namespace
}  // namespace texsynth
