// prepareSurface lays the neighbourhoods out on each level's mesh smoothed below its pixel scale:
// bumps an edge wide no longer stretch them, and the output keeps its own positions.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mesh_test_support.h"
#include "texsynth/surface/surface_synthesis.h"

using namespace texsynth;

namespace {

constexpr int kCells = 32;

// The unit square as a grid whose vertices are raised and lowered in a checkerboard by a
// quarter of an edge: at one pixel per vertex spacing, relief far below the texture's detail.
Mesh bumpySquare() {
  Mesh mesh = test::squareGrid(kCells);
  const float bump = 0.25f / kCells;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    const int x = int(v) % (kCells + 1), y = int(v) / (kCells + 1);
    mesh.positions[v].z() = (x + y) % 2 == 0 ? bump : -bump;
  }
  mesh.computeNormals();
  return mesh;
}

PreparedSurface preparedOf(const Mesh& mesh, int smoothing) {
  MeshHierarchy hierarchy;
  hierarchy.levels.push_back(
      MeshLevel{mesh, float(std::sqrt(mesh.surfaceArea() / double(mesh.vertexCount()))), {}, {}});
  SurfaceOrientation orientation;
  orientation.geometrySmoothing = smoothing;
  const std::vector<int> sizes = {5};
  return prepareSurface(std::move(hierarchy), orientation, sizes);
}

// Mean over the stencils of the grid's middle vertices of how far each member's unfolded
// distance from the centre (in cells) is from its distance in the square's plane.
double stencilStretch(const PreparedSurface& surface, const Mesh& flat) {
  const PreparedSurfaceLevel& level = surface.levels.back();
  const float spacing = surface.hierarchy.levels.back().spacing;
  double sum = 0;
  int count = 0;
  for (std::size_t v = 0; v < flat.vertexCount(); ++v) {
    const Vec3f& p = flat.positions[v];
    if (p.x() < 0.25f || p.x() > 0.75f || p.y() < 0.25f || p.y() > 0.75f) continue;
    for (const NeighborhoodMember& m : level.stencil.of(v)) {
      const float planar = (flat.positions[std::size_t(m.vertex)] - p).norm() / spacing;
      sum += std::abs(std::hypot(m.dx, m.dy) - planar), ++count;
    }
  }
  return sum / count;
}

TEST(SurfacePreparation, LaysNeighbourhoodsOutOnTheSurfaceSmoothedBelowItsPixelScale) {
  const Mesh flat = test::squareGrid(kCells);
  const Mesh bumpy = bumpySquare();
  const PreparedSurface raw = preparedOf(bumpy, 0);
  const PreparedSurface smoothed = preparedOf(bumpy, kSurfaceGeometrySmoothing);
  const double rawStretch = stencilStretch(raw, flat), smoothedStretch = stencilStretch(smoothed, flat);
  EXPECT_GT(rawStretch, 0.05) << "the bumps stretch the unfolded neighbourhoods";
  EXPECT_LT(smoothedStretch, 0.25 * rawStretch) << rawStretch << " on the mesh, " << smoothedStretch << " smoothed";
  // The synthesis reads the smoothed geometry; the output keeps the mesh's own bumps.
  EXPECT_EQ(smoothed.finestMesh().positions, bumpy.positions);
  EXPECT_NE(smoothed.levels.back().geometry.positions, bumpy.positions);
  EXPECT_EQ(smoothed.levels.back().geometry.triangles, bumpy.triangles);
}

TEST(SurfacePreparation, AFlatMeshIsLaidOutAsItIs) {
  // Smoothing moves vertices along their normals only: a plane keeps every vertex where it is, so
  // a coherent copy of the exemplar stays one (surface_parallel_test.cpp).
  const Mesh flat = test::squareGrid(kCells);
  const PreparedSurface smoothed = preparedOf(flat, kSurfaceGeometrySmoothing);
  EXPECT_EQ(smoothed.levels.back().geometry.positions, flat.positions);
}

}  // namespace
