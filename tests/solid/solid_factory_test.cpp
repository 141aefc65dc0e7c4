// The solid factory (shared by the command line, the demo and the studio): each method is the
// same texture as built by hand, the size rules apply, and inconsistent recipes are refused.
#include "texsynth/solid/solid_factory.h"

#include <gtest/gtest.h>

#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/solid/lazy_solid_texture.h"

namespace texsynth {
namespace {

SolidRecipe recipeFor(SolidMethod method, int side = 32) {
  SolidRecipe recipe;
  recipe.method = method;
  recipe.exemplars = {test::makeTestPattern(side, side, 4)};
  recipe.box.extend(Vec3f::Zero());
  recipe.box.extend(Vec3f(1.0f, 0.5f, 0.75f));
  recipe.tiles = 1.5f;
  recipe.seed = 9;
  return recipe;
}

std::vector<Vec3f> probePoints() {
  std::vector<Vec3f> points;
  for (int i = 0; i < 200; ++i) points.push_back(Vec3f(0.005f * i, 0.0021f * i, 0.7f - 0.003f * i));
  return points;
}

TEST(SolidFactory, TileDeformIsTheStackedSolidWithAQuarterExemplarCell) {
  const SolidRecipe recipe = recipeFor(SolidMethod::TileDeform);
  const SolidBuild build = buildSolid(recipe);
  TileDeformSolidOptions options;
  options.placement = fitPlacement(recipe.box, 32, recipe.tiles);
  options.deformation.cellSize = Vec3f::Constant(8.0f);
  options.deformation.seed = recipe.seed;
  const auto direct = makeStackedTileDeformSolid(recipe.exemplars[0], options);
  EXPECT_EQ(build.texture->evaluateColors(probePoints()), direct->evaluateColors(probePoints()));
  EXPECT_EQ(build.variant, "method 2: 2D exemplar stacked along xyz");
  EXPECT_FLOAT_EQ(build.placement.pixelsPerUnit, options.placement.pixelsPerUnit);
}

TEST(SolidFactory, LazyPicksItsLevelsAndPreparesTheCoarsestLevel) {
  SolidRecipe recipe = recipeFor(SolidMethod::Lazy, 20);
  recipe.lazy.levels = 0;
  recipe.lazy.neighborhoodSizes = {5};
  SolidBuild build = buildSolid(recipe);
  ASSERT_EQ(build.lazyParts.size(), 1u);
  const LazySolid& solid = *build.lazyParts[0].second;
  EXPECT_EQ(solid.levels(), lazyLevelsFor(20, 20, recipe.lazy));
  EXPECT_GT(solid.stats()[0].voxelsSynthesized, 0) << "the coarsest level is ready before any request";
  // The same solid built by hand gives the same colours.
  LazySolidOptions options = recipe.lazy;
  options.levels = solid.levels();
  options.seed = recipe.seed;
  setLazyDomain(options, build.placement, recipe.box);
  LazySolidTexture direct(std::make_shared<LazySolid>(recipe.exemplars[0], options), build.placement);
  const std::vector<Vec3f> points = probePoints();
  build.texture->prepare(points);
  direct.prepare(points);
  EXPECT_EQ(build.texture->evaluateColors(points), direct.evaluateColors(points));
}

TEST(SolidFactory, RefusesInconsistentRecipes) {
  SolidRecipe two = recipeFor(SolidMethod::Lazy);
  two.exemplars.push_back(two.exemplars[0]);
  test::expectParameterError([&] { buildSolid(two); }, "exemplar");
  SolidRecipe three = recipeFor(SolidMethod::TileBlend);
  three.exemplars = {three.exemplars[0], three.exemplars[0], three.exemplars[0]};
  test::expectParameterError([&] { buildSolid(three); }, "exemplar");
  SolidRecipe volume = recipeFor(SolidMethod::Lazy);
  volume.volume = Volume(4, 4, 4, 3);
  test::expectParameterError([&] { buildSolid(volume); }, "exemplar");
  SolidRecipe none = recipeFor(SolidMethod::TileDeform);
  none.exemplars.clear();
  test::expectParameterError([&] { buildSolid(none); }, "exemplar");
  SolidRecipe inner = recipeFor(SolidMethod::Lazy);
  inner.lazy.neighborhoodSizes = {5};
  inner.inner = inner.exemplars[0];
  test::expectParameterError([&] { buildSolid(inner); }, "inner");
  test::expectParameterError([] { parseSolidMethod("gradient"); }, "method");
  EXPECT_EQ(parseSolidMethod(solidMethodName(SolidMethod::TileBlend)), SolidMethod::TileBlend);
}

}  // namespace
}  // namespace texsynth
