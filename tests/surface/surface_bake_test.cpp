// Baking vertex colors into a UV layout: texels land where their UVs say (v up, row 0 at v = 1),
// interpolation is exact for colors linear in position, either chart winding counts, charts grow
// by the dilation and the rest gets the mean color, any thread count gives the same texture.
#include "texsynth/surface/surface_bake.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

using namespace texsynth;

namespace {

// The square [0, width] x [0, 1] in z = 0 as an n x n grid, with uv = (x, y) when `withUv`, and
// colors (x, y, 0.5) when `colored`; `mirrored` flips u (so the charts wind clockwise).
Mesh grid(int n, float width, bool withUv, bool colored, bool mirrored = false) {
  Mesh mesh;
  VertexAttribute uv{2, {}};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = width * float(i) / float(n), y = float(j) / float(n);
      mesh.positions.emplace_back(x, y, 0.0f);
      if (colored) mesh.colors.emplace_back(x, y, 0.5f);
      uv.values.push_back(mirrored ? 1.0f - x : x);
      uv.values.push_back(y);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int v = j * (n + 1) + i;
      mesh.triangles.emplace_back(v, v + 1, v + n + 2);
      mesh.triangles.emplace_back(v, v + n + 2, v + n + 1);
    }
  if (withUv) mesh.attributes[kUvAttribute] = uv;
  mesh.computeNormals();
  return mesh;
}

// The texel's centre in UV space.
Vec2f texelUv(int x, int y, int size) {
  return {(float(x) + 0.5f) / float(size), 1.0f - (float(y) + 0.5f) / float(size)};
}

TEST(SurfaceBake, TexelsGetTheColorOfTheirSurfacePoint) {
  const Mesh colored = grid(17, 1.0f, false, true);  // another tessellation than the UV mesh
  for (bool mirrored : {false, true}) {
    SurfaceBakeOptions options;
    options.size = 32;
    const Image baked = bakeVertexColors(grid(5, 1.0f, true, false, mirrored), colored, options);
    ASSERT_EQ(baked.width, 32);
    ASSERT_EQ(baked.height, 32);
    ASSERT_EQ(baked.channels, 3);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const Vec2f uv = texelUv(x, y, 32);
        const float surfaceX = mirrored ? 1.0f - uv.x() : uv.x();
        ASSERT_NEAR(baked.at(x, y, 0), surfaceX, 1e-4f) << x << "," << y << " mirrored " << mirrored;
        ASSERT_NEAR(baked.at(x, y, 1), uv.y(), 1e-4f) << x << "," << y;
        ASSERT_NEAR(baked.at(x, y, 2), 0.5f, 1e-6f);
      }
  }
}

TEST(SurfaceBake, ChartsGrowByTheDilationAndTheRestIsTheMeanColor) {
  // The UV mesh covers u in [0, 0.5]: its texels are columns 0..15 of 32.
  Mesh uvMesh = grid(4, 0.5f, true, false);
  Mesh colored = uvMesh;
  colored.attributes.clear();
  colored.colors.assign(colored.vertexCount(), Vec3f(0.2f, 0.4f, 0.6f));
  colored.colors[0] = Vec3f(1, 1, 1);  // one bright corner, so the mean is not any texel's color
  SurfaceBakeOptions options;
  options.size = 32;
  options.dilation = 3;
  const Image baked = bakeVertexColors(uvMesh, colored, options);
  Vec3f mean = Vec3f::Zero();
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 16; ++x) mean += Vec3f(baked.at(x, y, 0), baked.at(x, y, 1), baked.at(x, y, 2));
  for (int y = 0; y < 32; ++y) {
    // Columns 16..18 repeat the chart's edge (each dilation ring averages the ring before).
    for (int x = 16; x < 19; ++x) EXPECT_NEAR(baked.at(x, y, 1), baked.at(15, y, 1), 0.05f) << x << "," << y;
    // Further out every texel has one color: the mean of the baked ones (dilated ones included).
    for (int x = 19; x < 32; ++x) ASSERT_EQ(baked.at(x, y, 0), baked.at(31, 0, 0));
  }
  EXPECT_GT(baked.at(31, 0, 0), 0.2f);
  EXPECT_LT(baked.at(31, 0, 0), 1.0f);
}

TEST(SurfaceBake, SameTextureForAnyThreadCount) {
  const Mesh uvMesh = grid(6, 1.0f, true, false), colored = grid(11, 1.0f, false, true);
  SurfaceBakeOptions options;
  options.size = 48;
  Image one, two;
  {
    ThreadLimit limit(1);
    one = bakeVertexColors(uvMesh, colored, options);
  }
  {
    ThreadLimit limit(2);
    two = bakeVertexColors(uvMesh, colored, options);
  }
  EXPECT_EQ(one.pixels, two.pixels);
}

TEST(SurfaceBake, RejectsMeshesWithoutUvsOrColorsAndBadSizes) {
  const Mesh uvMesh = grid(2, 1.0f, true, false), colored = grid(2, 1.0f, false, true);
  test::expectParameterError([&] { bakeVertexColors(colored, colored); }, "uv");
  test::expectParameterError([&] { bakeVertexColors(uvMesh, uvMesh); }, "colors");
  for (int size : {0, -4, 16385}) {
    SurfaceBakeOptions options;
    options.size = size;
    test::expectParameterError([&] { bakeVertexColors(uvMesh, colored, options); }, "size");
  }
  SurfaceBakeOptions options;
  options.dilation = -2;
  test::expectParameterError([&] { bakeVertexColors(uvMesh, colored, options); }, "dilation");
}

}  // namespace
