#include "texsynth/solid/tile_deform_solid.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "solid_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

using namespace texsynth;

namespace {

std::vector<float> evaluateAll(const SolidTexture& solid, const std::vector<Vec3f>& points,
                               const std::vector<Vec3f>& normals = {}) {
  std::vector<float> values(points.size() * std::size_t(solid.channels()));
  solid.evaluate(points, normals, values);
  return values;
}

using test::expectParameterError;

}  // namespace

TEST(TileDeformSolid, ZeroLambdaIsPlainVolumeTiling) {
  const Volume exemplar = test::makeTestVolume(16);
  TileDeformSolidOptions options;
  options.deformation.lambda = Vec3f::Zero();
  options.placement.pixelsPerUnit = 3.0f;
  auto solid = makeTileDeformSolid(exemplar, options);
  const auto points = test::randomPoints(500, 40.0f);
  const auto values = evaluateAll(*solid, points);
  float expected[3];
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3f q = points[i] * 3.0f;
    exemplar.sampleTrilinearWrapped(q.x(), q.y(), q.z(), expected);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(values[i * 3 + c], expected[c]);
  }
}

TEST(TileDeformSolid, ZeroLambdaIsPlainStacking) {
  const Image exemplar = test::makeTestPattern(32, 24);
  TileDeformSolidOptions options;
  options.deformation.lambda = Vec3f::Zero();
  const auto points = test::randomPoints(300, 100.0f);
  float expected[4];
  for (StackAxes axes : {StackAxes::X, StackAxes::Y, StackAxes::Z}) {
    options.stacking = axes;
    const auto values = evaluateAll(*makeStackedTileDeformSolid(exemplar, options), points);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec3f& p = points[i];
      const Vec2f uv = axes == StackAxes::X   ? Vec2f(p.y(), p.z())
                       : axes == StackAxes::Y ? Vec2f(p.x(), p.z())
                                              : Vec2f(p.x(), p.y());
      exemplar.sampleBilinearWrapped(uv.x(), uv.y(), expected);
      for (int c = 0; c < exemplar.channels; ++c) ASSERT_EQ(values[i * exemplar.channels + c], expected[c]);
    }
  }
}

TEST(TileDeformSolid, ZStackingIsConstantAlongZWithoutInPlaneDeformation) {
  const Image exemplar = test::makeTestPattern(32, 32);
  TileDeformSolidOptions options;
  options.stacking = StackAxes::Z;
  options.deformation.lambda = Vec3f(0.0f, 0.0f, 0.4f);  // λ_z moves only the ignored coordinate
  auto flat = makeStackedTileDeformSolid(exemplar, options);
  options.deformation.lambda = Vec3f(0.4f, 0.4f, 0.0f);
  auto deformed = makeStackedTileDeformSolid(exemplar, options);
  std::vector<Vec3f> column;
  for (int z = 0; z < 64; ++z) column.push_back(Vec3f(13.3f, 7.9f, float(z) * 5.0f));
  const auto flatValues = evaluateAll(*flat, column), deformedValues = evaluateAll(*deformed, column);
  int deformedChanges = 0;
  for (std::size_t i = 1; i < column.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(flatValues[i * 3 + c], flatValues[c]);
      deformedChanges += deformedValues[i * 3 + c] != deformedValues[c];
    }
  EXPECT_GT(deformedChanges, 0) << "3D deformation must vary the stacked image along z";
}

TEST(TileDeformSolid, DeformationChangesTheResult) {
  auto plain = TileDeformSolidOptions{};
  plain.deformation.lambda = Vec3f::Zero();
  const Volume exemplar = test::makeTestVolume(16);
  const auto points = test::randomPoints(400, 200.0f);
  const auto a = evaluateAll(*makeTileDeformSolid(exemplar, plain), points);
  const auto b = evaluateAll(*makeTileDeformSolid(exemplar, {}), points);
  int differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differing += std::abs(a[i] - b[i]) > 1e-3f;
  EXPECT_GT(differing, int(a.size()) / 2);
}

TEST(TileDeformSolid, DeterministicAcrossThreadsBatchesAndOrder) {
  const Image exemplar = test::makeTestPattern(48, 48);
  auto solid = makeStackedTileDeformSolid(exemplar, {});
  const auto points = test::randomPoints(20000, 500.0f);
  const auto normals = test::randomNormals(20000);
  std::vector<float> reference;
  {
    ThreadLimit one(1);
    reference = evaluateAll(*solid, points, normals);
  }
  std::vector<float> parallel;
  {
    ThreadLimit two(2);
    parallel = evaluateAll(*solid, points, normals);
  }
  EXPECT_EQ(parallel, reference);
  // Reversed order, evaluated in small uneven serial batches.
  std::vector<Vec3f> reversedPoints(points.rbegin(), points.rend()), reversedNormals(normals.rbegin(), normals.rend());
  std::vector<float> reversed(reference.size());
  const std::span<const Vec3f> rp(reversedPoints), rn(reversedNormals);
  for (std::size_t begin = 0; begin < points.size(); begin += 37) {
    const std::size_t count = std::min<std::size_t>(37, points.size() - begin);
    solid->evaluateSerial(rp.subspan(begin, count), rn.subspan(begin, count),
                          std::span<float>(reversed).subspan(begin * 3, count * 3));
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(reversed[(points.size() - 1 - i) * 3 + c], reference[i * 3 + c]);
}

TEST(TileDeformSolid, SeedChangesDeformation) {
  const Volume exemplar = test::makeTestVolume(16);
  TileDeformSolidOptions other;
  other.deformation.seed = 2;
  const auto points = test::randomPoints(200, 300.0f);
  EXPECT_NE(evaluateAll(*makeTileDeformSolid(exemplar, {}), points),
            evaluateAll(*makeTileDeformSolid(exemplar, other), points));
}

TEST(TileDeformSolid, DeformedCornersStayWithinTheClamp) {
  GridDeformationOptions options;
  options.lambda = Vec3f(5.0f, 5.0f, 5.0f);  // noise * λ far past the clamp
  options.clamp = 0.3f;
  GridDeformation3d deformation(options);
  float largest = 0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      largest = std::max(largest, deformation.cornerDisplacement(i, j, i - j).cwiseAbs().maxCoeff());
  EXPECT_LE(largest, 0.3f * 32.0f);
  EXPECT_GT(largest, 0.29f * 32.0f);
}

TEST(TileDeformSolid, BadParametersRejected) {
  const Image image = test::makeTestPattern(8, 8);
  auto withOption = [&](auto change, const std::string& parameter) {
    TileDeformSolidOptions options;
    change(options);
    expectParameterError([&] { makeStackedTileDeformSolid(image, options); }, parameter);
  };
  withOption([](auto& o) { o.deformation.cellSize.y() = 0; }, "deformation.cellSize");
  withOption([](auto& o) { o.deformation.lambda.x() = -0.1f; }, "deformation.lambda");
  withOption([](auto& o) { o.deformation.clamp = 0.5f; }, "deformation.clamp");
  withOption([](auto& o) { o.deformation.noiseScale = std::nanf(""); }, "deformation.noiseScale");
  withOption([](auto& o) { o.placement.pixelsPerUnit = 0; }, "placement.pixelsPerUnit");
  withOption([](auto& o) { o.blendSharpness = 0; }, "blendSharpness");
  expectParameterError([] { makeStackedTileDeformSolid(Image(), {}); }, "exemplar");
  expectParameterError([] { makeTileDeformSolid(Volume(), {}); }, "exemplar");
  auto solid = makeStackedTileDeformSolid(image, {});
  std::vector<Vec3f> points(4, Vec3f::Zero()), normals(3, Vec3f::UnitZ());
  std::vector<float> values(12);
  expectParameterError([&] { solid->evaluate(points, normals, values); }, "normals");
  values.resize(11);
  expectParameterError([&] { solid->evaluate(points, {}, values); }, "values");
}
