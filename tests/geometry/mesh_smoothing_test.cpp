// Taubin smoothing: bumps an edge or two wide go, the shape stays (no shrinking), vertices move
// along their normals only, borders stay.
#include "texsynth/geometry/mesh_smoothing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/mesh_test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

// A height that alternates between neighbouring vertices of an n x n grid (a checkerboard): the
// finest bump a mesh can carry.
float bump(int v, int n) {
  return (v % (n + 1) + v / (n + 1)) % 2 == 0 ? 0.01f : -0.01f;
}

// Over the vertices at least 4 edges from the grid's (fixed) border.
double rmsInteriorHeight(const Mesh& mesh, int n) {
  double sum = 0;
  int count = 0;
  for (int y = 4; y <= n - 4; ++y)
    for (int x = 4; x <= n - 4; ++x, ++count)
      sum += std::pow(double(mesh.positions[std::size_t(y * (n + 1) + x)].z()), 2);
  return std::sqrt(sum / count);
}

TEST(MeshSmoothing, RemovesBumpsAnEdgeWideAndKeepsTheBorder) {
  const int n = 24;
  Mesh grid = test::squareGrid(n);
  for (std::size_t v = 0; v < grid.vertexCount(); ++v) grid.positions[v].z() = bump(int(v), n);
  grid.computeNormals();
  const MeshTopology topology(grid, "grid");
  const Mesh smoothed = taubinSmoothed(grid, topology, 10);
  ASSERT_EQ(smoothed.vertexCount(), grid.vertexCount());
  EXPECT_EQ(smoothed.triangles, grid.triangles);
  EXPECT_LT(rmsInteriorHeight(smoothed, n), 0.05 * rmsInteriorHeight(grid, n));
  for (int v = 0; v < topology.vertexCount(); ++v) {
    if (topology.isBorderVertex(v)) {
      EXPECT_EQ(smoothed.positions[std::size_t(v)], grid.positions[std::size_t(v)]);
    }
  }
  ASSERT_EQ(smoothed.normals.size(), smoothed.vertexCount());
  int upward = 0;
  for (const Vec3f& normal : smoothed.normals) upward += normal.z() > 0.99f;
  EXPECT_GT(upward, int(smoothed.vertexCount()) / 2);  // the bumps' tilted normals are gone inside
}

TEST(MeshSmoothing, MovesVerticesAlongTheirNormalsOnly) {
  // An irregular flat grid keeps every vertex where it is (a uniform Laplacian would slide them
  // along the plane towards their neighbours' mean).
  const int n = 16;
  Mesh grid = test::squareGrid(n);
  for (std::size_t v = 0; v < grid.vertexCount(); ++v) {
    const int x = int(v) % (n + 1), y = int(v) / (n + 1);
    if (x == 0 || y == 0 || x == n || y == n) continue;
    grid.positions[v].x() += 0.3f / n * std::sin(float(7 * v));
    grid.positions[v].y() += 0.3f / n * std::cos(float(5 * v));
  }
  grid.computeNormals();
  EXPECT_EQ(taubinSmoothed(grid, MeshTopology(grid, "grid"), 10).positions, grid.positions);
}

TEST(MeshSmoothing, KeepsTheShapeOfASmoothSurface) {
  // Plain Laplacian smoothing would pull the sphere in by several percent; Taubin's inflating
  // step keeps its radius.
  const Mesh sphere = test::icosphere(4);
  const Mesh smoothed = taubinSmoothed(sphere, MeshTopology(sphere, "sphere"), 10);
  for (const Vec3f& p : smoothed.positions) EXPECT_NEAR(p.norm(), 1.0f, 0.01f);
}

TEST(MeshSmoothing, ZeroPassesCopiesAndNegativeIsAnError) {
  const Mesh sphere = test::irregularSphere(2);
  const MeshTopology topology(sphere, "sphere");
  EXPECT_EQ(taubinSmoothed(sphere, topology, 0).positions, sphere.positions);
  EXPECT_THROW(taubinSmoothed(sphere, topology, -1), ParameterError);
}

TEST(MeshSmoothing, SameBitsForAnyThreadCount) {
  const Mesh sphere = test::irregularSphere(5);
  const MeshTopology topology(sphere, "sphere");
  std::vector<Vec3f> one, two;
  {
    ThreadLimit limit(1);
    one = taubinSmoothed(sphere, topology, 2).positions;
  }
  {
    ThreadLimit limit(2);
    two = taubinSmoothed(sphere, topology, 2).positions;
  }
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace texsynth
