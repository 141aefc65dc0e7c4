// Options in, a SolidTexture out: the one construction of tile-deform, tile-blend and lazy solids.
#include "texsynth/solid/solid_factory.h"

#include <algorithm>
#include <chrono>

#include "texsynth/core/error.h"
#include "texsynth/solid/lazy_field.h"
#include "texsynth/solid/lazy_solid_texture.h"
#include "texsynth/solid/region_solid.h"

namespace texsynth {

namespace {

std::shared_ptr<LazySolid> makeLazySynthesis(const std::vector<Image>& images, const LazySolidOptions& options,
                                             const LazyOrientation& orientation) {
  if (images.size() == 1) return std::make_shared<LazySolid>(images[0], options, orientation);
  return std::make_shared<LazySolid>(images[0], images[1], images[2], options, orientation);
}

// The coarsest level over the whole box once (from the disk cache when this model and exemplar
// were synthesized before): every surface, slice or cut inside then reuses it.
double prepareCoarsest(LazySolidTexture& texture, Progress& progress) {
  const auto started = std::chrono::steady_clock::now();
  texture.solid().prepareCoarsestLevel(progress);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

SolidBuild buildLazy(const SolidRecipe& recipe, const SolidPlacement& placement, Progress& progress) {
  const std::vector<Image>& images = recipe.exemplars;
  LazySolidOptions options = recipe.lazy;
  // Without a level count, up to 4, fewer where the coarsest neighbourhood would not fit the exemplar.
  if (options.levels <= 0) options.levels = lazyLevelsFor(images[0].width, images[0].height, options);
  options.seed = recipe.seed;
  setLazyDomain(options, placement, recipe.box);
  LazyOrientation orientation;
  if (recipe.field) {
    orientation = lazyOrientationFromField(*recipe.field, placement, options.levels);
    options.orientationKey = lazyOrientationKey(*recipe.field, placement, options.levels);
  }
  SolidBuild build;
  build.placement = placement;
  build.variant = recipe.field ? "lazy, guided by a field" : "lazy, identity field";
  auto outer = makeLazySynthesis(images, options, orientation);
  build.lazyParts.push_back({"shell", outer});
  auto outerTexture = std::make_shared<LazySolidTexture>(outer, placement);
  build.coarsestSeconds = prepareCoarsest(*outerTexture, progress);
  if (!recipe.inner) {
    build.texture = std::make_unique<LazySolidTexture>(outer, placement);
    return build;
  }
  if (!recipe.mesh || recipe.mesh->positions.empty())
    throw ParameterError("inner", "needs a mesh: the regions are depths below its surface");
  LazySolidOptions innerOptions = options;
  innerOptions.seed = recipe.seed ^ 0x1a2b3c4d5e6fULL;  // independent of the shell's synthesis
  innerOptions.featureMasks.clear();                    // the masks describe the shell's exemplars
  auto inner = makeLazySynthesis({*recipe.inner}, innerOptions, orientation);
  build.lazyParts.push_back({"core", inner});
  auto innerTexture = std::make_shared<LazySolidTexture>(inner, placement);
  build.coarsestSeconds += prepareCoarsest(*innerTexture, progress);
  build.texture =
      std::make_unique<RegionSolidTexture>(std::vector<std::shared_ptr<SolidTexture>>{outerTexture, innerTexture},
                                           surfaceShellRule(*recipe.mesh, recipe.shellDepth));
  return build;
}

}  // namespace

SolidMethod parseSolidMethod(const std::string& name) {
  if (name == "tile-deform") return SolidMethod::TileDeform;
  if (name == "tile-blend") return SolidMethod::TileBlend;
  if (name == "lazy") return SolidMethod::Lazy;
  throw ParameterError("method", "'" + name + "': give tile-deform, tile-blend or lazy");
}

const char* solidMethodName(SolidMethod method) {
  switch (method) {
    case SolidMethod::TileDeform:
      return "tile-deform";
    case SolidMethod::TileBlend:
      return "tile-blend";
    case SolidMethod::Lazy:
      return "lazy";
  }
  return "?";
}

SolidBuild buildSolid(const SolidRecipe& recipe, Progress& progress) {
  const bool volume = recipe.volume.has_value();
  if (volume && recipe.method != SolidMethod::TileDeform)
    throw ParameterError("exemplar", std::string(solidMethodName(recipe.method)) + " takes 2D exemplars, not a volume");
  if (!volume && recipe.exemplars.empty()) throw ParameterError("exemplar", "give an exemplar");
  if (recipe.exemplars.size() == 2 || recipe.exemplars.size() > 3)
    throw ParameterError("exemplar", "give one exemplar for all three planes, or three: XY YZ ZX");
  if (recipe.exemplars.size() == 3 && recipe.method != SolidMethod::Lazy)
    throw ParameterError("exemplar", "only lazy takes three exemplars (XY YZ ZX)");
  if (recipe.inner && recipe.method != SolidMethod::Lazy)
    throw ParameterError("inner", "an inner exemplar is a lazy option here");
  const int tileSide = volume ? std::max({recipe.volume->nx, recipe.volume->ny, recipe.volume->nz})
                              : std::max(recipe.exemplars[0].width, recipe.exemplars[0].height);
  const SolidPlacement placement = fitPlacement(recipe.box, tileSide, recipe.tiles);
  if (recipe.method == SolidMethod::Lazy) return buildLazy(recipe, placement, progress);

  SolidBuild build;
  build.placement = placement;
  if (recipe.method == SolidMethod::TileBlend) {
    TileBlendSolidOptions options = recipe.tileBlend;
    options.placement = placement;
    options.seed = recipe.seed;
    build.variant = "triplanar tile-blend";
    build.texture = makeTileBlendSolid(recipe.exemplars[0], options);
    return build;
  }
  TileDeformSolidOptions options = recipe.tileDeform;
  options.placement = placement;
  for (int a = 0; a < 3; ++a)
    if (options.deformation.cellSize[a] == 0) options.deformation.cellSize[a] = 0.25f * tileSide;  // as in 2D
  options.deformation.seed = recipe.seed;
  if (volume) {
    build.variant = "method 1: 3D exemplar";
    build.texture = makeTileDeformSolid(*recipe.volume, options);
  } else {
    static const char* const kStacking[] = {"x", "y", "z", "xyz"};
    build.variant = std::string("method 2: 2D exemplar stacked along ") + kStacking[int(options.stacking)];
    build.texture = makeStackedTileDeformSolid(recipe.exemplars[0], options);
  }
  return build;
}

void PointRecorder::evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f>,
                                   std::span<float> values) const {
  std::fill(values.begin(), values.end(), 0.0f);
  std::lock_guard<std::mutex> lock(mutex_);
  points_.insert(points_.end(), points.begin(), points.end());
}

std::vector<Vec3f> PointRecorder::take() {
  return std::move(points_);
}

}  // namespace texsynth
