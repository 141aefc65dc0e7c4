#include "texsynth/solid/tile_blend_solid.h"

#include <gtest/gtest.h>

#include "solid_test_support.h"
#include "test_support.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/eval/histogram_distance.h"
#include "texsynth/io/image_io.h"
#include "texsynth/solid/solid_consumers.h"

using namespace texsynth;

namespace {

Image exemplarForTest() {
  if (auto path = gimpPattern("Stone/marble1.pat")) return readImage(*path).withChannels(3);
  return test::makeTestPattern(64, 64);
}

Box3f cube(float side) {
  Box3f box;
  box.extend(Vec3f::Zero());
  box.extend(Vec3f::Constant(side));
  return box;
}

}  // namespace

TEST(TileBlendSolid, SlicesKeepTheExemplarHistogram) {
  const Image exemplar = exemplarForTest();
  auto solid = makeTileBlendSolid(exemplar, {});
  for (int axis = 0; axis < 3; ++axis) {
    const Image slice = sampleSlice(*solid, cube(384.0f), axis, 0.37f, 192);
    // evaluateImage's histogram metric (0..255 units) without its slow patch metrics. Plain
    // averaging of the three planes would shrink the variance and score far higher.
    const double distance = 255.0 * histogramDistance(exemplar, slice);
    EXPECT_LT(distance, 4.0) << "axis " << axis;
  }
}

TEST(TileBlendSolid, DeterministicAcrossThreadsAndBatchSplit) {
  auto solid = makeTileBlendSolid(test::makeTestPattern(32, 32), {});
  const auto points = test::randomPoints(10000, 1000.0f);
  const auto normals = test::randomNormals(10000);
  std::vector<Vec3f> one, two;
  {
    ThreadLimit limit(1);
    one = solid->evaluateColors(points, normals);
  }
  {
    ThreadLimit limit(2);
    two = solid->evaluateColors(points, normals);
  }
  EXPECT_EQ(one, two);
  const std::span<const Vec3f> p(points), n(normals);
  for (std::size_t i : {0ul, 4095ul, 4096ul, 9999ul})
    EXPECT_EQ(solid->evaluateColors(p.subspan(i, 1), n.subspan(i, 1))[0], one[i]);
}

TEST(TileBlendSolid, AxisNormalUsesOnePlaneOnly) {
  // With normal +z only the z plane contributes: the colour cannot change along z.
  auto solid = makeTileBlendSolid(test::makeTestPattern(32, 32), {});
  std::vector<Vec3f> column, normals;
  for (int z = 0; z < 20; ++z) {
    column.push_back(Vec3f(5.5f, 9.25f, float(z) * 7.0f));
    normals.push_back(Vec3f::UnitZ());
  }
  const auto colors = solid->evaluateColors(column, normals);
  for (const Vec3f& c : colors) EXPECT_EQ(c, colors[0]);
}

TEST(TileBlendSolid, BadParametersRejected) {
  const Image image = test::makeTestPattern(8, 8);
  auto expectError = [&](TileBlendSolidOptions options, const std::string& parameter) {
    test::expectParameterError([&] { makeTileBlendSolid(image, options); }, parameter);
  };
  TileBlendSolidOptions o;
  o.tileSize = -1;
  expectError(o, "tileSize");
  o = {};
  o.weightExponent = 0.5f;
  expectError(o, "weightExponent");
  o = {};
  o.blendSharpness = 100;
  expectError(o, "blendSharpness");
  o = {};
  o.placement.origin.x() = std::nanf("");
  expectError(o, "placement.origin");
  o = {};
  o.gaussianization.lutSize = 1;
  expectError(o, "lutSize");
  EXPECT_THROW(makeTileBlendSolid(Image(), {}), ParameterError);
}
