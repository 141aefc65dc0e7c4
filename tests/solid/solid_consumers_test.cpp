#include "texsynth/solid/solid_consumers.h"

#include <gtest/gtest.h>

#include "solid_test_support.h"
#include "test_support.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"
#include "texsynth/solid/tile_deform_solid.h"

using namespace texsynth;

namespace {

Box3f unitBox() {
  Box3f box;
  box.extend(Vec3f(-1.0f, 0.0f, 2.0f));
  box.extend(Vec3f(1.0f, 1.5f, 3.0f));
  return box;
}

std::unique_ptr<SolidTexture> volumeSolid() {
  TileDeformSolidOptions options;
  options.placement.pixelsPerUnit = 20.0f;
  options.deformation.cellSize = Vec3f(8, 8, 8);
  return makeTileDeformSolid(test::makeTestVolume(16), options);
}

}  // namespace

TEST(SolidConsumers, SliceEqualsVolumePlane) {
  auto solid = volumeSolid();
  const Box3f box = unitBox();
  const Volume volume = sampleVolume(*solid, box, 24);
  ASSERT_EQ(volume.nx, 24);
  ASSERT_EQ(volume.ny, 18);
  ASSERT_EQ(volume.nz, 12);
  const int n[3] = {volume.nx, volume.ny, volume.nz};
  for (int axis = 0; axis < 3; ++axis) {
    const int k = n[axis] / 3;
    const Image slice = sampleSlice(*solid, box, axis, (float(k) + 0.5f) / float(n[axis]), 24);
    for (int v = 0; v < slice.height; ++v)
      for (int u = 0; u < slice.width; ++u) {
        int x = axis == 0 ? k : u, y = axis == 1 ? k : (axis == 0 ? u : v), z = axis == 2 ? k : v;
        for (int c = 0; c < 3; ++c) ASSERT_EQ(slice.at(u, v, c), volume.at(x, y, z, c)) << "axis " << axis;
      }
  }
}

TEST(SolidConsumers, SliceRejectsBadRequests) {
  auto solid = volumeSolid();
  EXPECT_THROW(sampleSlice(*solid, unitBox(), 3, 0.5f, 8), ParameterError);
  EXPECT_THROW(sampleSlice(*solid, unitBox(), 2, 1.5f, 8), ParameterError);
}

TEST(SolidConsumers, RenderAdapterEvaluatesEveryPixel) {
  auto solid = volumeSolid();
  Mesh sphere = makeUvSphereMesh(Vec3f::Zero(), 1.0f, 24, 24);
  RenderOptions options;
  options.width = options.height = 64;
  const Image perPixel = renderMesh(sphere, surfaceColorFunction(*solid), options);
  colorMeshVertices(sphere, *solid);
  const Image perVertex = renderMesh(sphere, options);
  ASSERT_EQ(perPixel.width, 64);
  double difference = 0;
  for (std::size_t i = 0; i < perPixel.pixels.size(); ++i)
    difference += std::abs(perPixel.pixels[i] - perVertex.pixels[i]);
  EXPECT_GT(difference, 1.0) << "per-pixel colours must not be interpolated vertex colours";
}

TEST(SolidConsumers, ColorsRealMeshVertices) {
  auto path = cgalMesh("bunny00.off");
  TS_REQUIRE_DATA(path);
  Mesh mesh = readMesh(*path);
  TileDeformSolidOptions options;
  options.placement = fitPlacement(mesh.bounds(), 64, 3.0f);
  auto solid = makeStackedTileDeformSolid(test::makeTestPattern(64, 64), options);
  colorMeshVertices(mesh, *solid);
  ASSERT_EQ(mesh.colors.size(), mesh.vertexCount());
  ASSERT_EQ(mesh.normals.size(), mesh.vertexCount());
  Vec3f mean = Vec3f::Zero();
  for (const Vec3f& c : mesh.colors) {
    ASSERT_TRUE(c.allFinite());
    mean += c;
  }
  mean /= float(mesh.colors.size());
  float variance = 0;
  for (const Vec3f& c : mesh.colors) variance += (c - mean).squaredNorm();
  EXPECT_GT(variance / float(mesh.colors.size()), 1e-3f) << "the texture must vary over the bunny";
}

TEST(SolidConsumers, FitPlacementSpansTheRequestedTiles) {
  const SolidPlacement placement = fitPlacement(unitBox(), 64, 2.0f);
  EXPECT_EQ(placement.origin, unitBox().min);
  EXPECT_FLOAT_EQ(placement.pixelsPerUnit * 2.0f, 128.0f);  // longest side 2 units -> 128 pixels
  EXPECT_THROW(fitPlacement(unitBox(), 0, 2.0f), ParameterError);
  EXPECT_THROW(fitPlacement(unitBox(), 64, 0.0f), ParameterError);
}
