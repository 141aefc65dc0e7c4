// texsynth solid --method lazy: building the lazy synthesis (exemplars, field, regions) and
// reporting its work.
#include <chrono>

#include "solid_args.h"
#include "texsynth/field/field_designer.h"
#include "texsynth/field/field_io.h"
#include "texsynth/field/sketch.h"
#include "texsynth/io/image_io.h"
#include "texsynth/solid/lazy_field.h"
#include "texsynth/solid/lazy_solid_texture.h"
#include "texsynth/solid/region_solid.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

// The exemplar images: one for all planes or three (XY YZ ZX).
std::vector<Image> readExemplars(const std::vector<std::string>& exemplars) {
  if (exemplars.size() == 2)
    throw ParameterError("EXEMPLAR", "give one exemplar for all three planes, or three: XY YZ ZX");
  return readImages(exemplars);
}

// One LazySolid on one exemplar (all planes) or three (XY YZ ZX).
std::shared_ptr<LazySolid> makeSynthesis(const std::vector<Image>& images, const LazySolidOptions& options,
                                         const LazyOrientation& orientation) {
  if (images.size() == 1) return std::make_shared<LazySolid>(images[0], options, orientation);
  return std::make_shared<LazySolid>(images[0], images[1], images[2], options, orientation);
}

}  // namespace

LazyBuild makeLazySolid(const SolidArgs& args, const Mesh& mesh, const Box3f& box, const SolidPlacement& placement,
                        std::uint64_t seed, json& report, Progress& progress) {
  const std::vector<Image> images = readExemplars(args.exemplars);
  LazySolidOptions options;
  // Without --levels, up to 4, fewer where the coarsest neighbourhood would not fit the exemplar.
  options.levels = args.levels > 0 ? args.levels : lazyLevelsFor(images[0].width, images[0].height, options);
  options.passes = args.passes;
  options.coarsestPasses = args.coarsestPasses;
  options.dualGrid = args.dualGrid;
  options.gridCellSize = args.gridCell;
  options.subpassGrid = args.subpasses;
  options.candidateCount = args.candidates;
  options.colorRule =
      args.colorRule == "mean" ? LazySolidOptions::ColorRule::Mean : LazySolidOptions::ColorRule::Medoid;
  options.seed = seed;
  options.cacheDirectory = defaultCacheDirectory();
  setLazyDomain(options, placement, box);
  if (!args.masks.empty() && args.masks.size() != 1 && args.masks.size() != args.exemplars.size())
    throw ParameterError("--mask", "give one mask for all planes, or one per exemplar (XY YZ ZX)");
  options.featureMasks = readImages(args.masks);
  LazyOrientation orientation;
  if (!args.field.empty()) {
    const RotationField field = readField(args.field).rotations;
    orientation = lazyOrientationFromField(field, placement, options.levels);
    options.orientationKey = lazyOrientationKey(field, placement, options.levels);
    report["field"] = args.field;
  } else if (!args.sketch.empty()) {
    if (mesh.positions.empty()) throw ParameterError("--sketch", "needs --mesh: the field is designed around it");
    const FieldDesign design = designField(mesh, readSketch(args.sketch), {}, noProgress(), args.sketch);
    orientation = lazyOrientationFromField(design.rotations, placement, options.levels);
    options.orientationKey = lazyOrientationKey(design.rotations, placement, options.levels);
    report["sketch"] = args.sketch;
  }
  report["variant"] = !args.field.empty()    ? "lazy, guided by --field"
                      : !args.sketch.empty() ? "lazy, guided by the field of --sketch"
                                             : "lazy, identity field";

  LazyBuild build;
  auto outer = makeSynthesis(images, options, orientation);
  build.parts.push_back({"shell", outer});
  auto outerTexture = std::make_shared<LazySolidTexture>(outer, placement);
  // The coarsest level over the whole box once (as the paper does for its volume; from the disk
  // cache when this model and exemplar were synthesized before): every surface, slice or cut
  // inside then reuses it.
  report["coarsest_level"]["seconds"] = 0.0;  // shell and core together
  const auto coarsest = [&](LazySolidTexture& texture) {
    const auto started = std::chrono::steady_clock::now();
    texture.solid().prepareCoarsestLevel(progress);
    json& seconds = report["coarsest_level"]["seconds"];
    seconds = seconds.get<double>() + std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  coarsest(*outerTexture);
  if (args.inner.empty()) {
    build.texture = std::make_unique<LazySolidTexture>(outer, placement);
    return build;
  }
  if (mesh.positions.empty()) throw ParameterError("--inner", "needs --mesh: the regions are depths below its surface");
  LazySolidOptions innerOptions = options;
  innerOptions.seed = seed ^ 0x1a2b3c4d5e6fULL;  // independent of the shell's synthesis
  innerOptions.featureMasks.clear();             // --mask describes the shell's exemplars
  auto inner = makeSynthesis({readImage(args.inner)}, innerOptions, orientation);
  build.parts.push_back({"core", inner});
  const float depth = args.shell * mesh.bounds().size().norm();
  report["shell_depth"] = depth;
  auto innerTexture = std::make_shared<LazySolidTexture>(inner, placement);
  coarsest(*innerTexture);
  build.texture = std::make_unique<RegionSolidTexture>(
      std::vector<std::shared_ptr<SolidTexture>>{outerTexture, innerTexture}, surfaceShellRule(mesh, depth));
  return build;
}

json lazyStats(const LazyBuild& build) {
  json parts = json::array();
  for (const auto& [name, synthesis] : build.parts) {
    json levels = json::array();
    for (int l = 0; l < synthesis->levels(); ++l) {
      const LazyLevelStats& st = synthesis->stats()[std::size_t(l)];
      levels.push_back({{"level", l},
                        {"voxels_synthesized", st.voxelsSynthesized},
                        {"corrections", st.corrections},
                        {"comparisons", st.comparisons},
                        {"blocks_cached", st.blocksCached},
                        {"seconds", st.seconds},
                        {"peak_working_mib", double(st.peakWorkingBytes) / (1 << 20)},
                        {"cached_mib", double(st.cachedBytes) / (1 << 20)},
                        {"from_disk_cache", st.fromDiskCache}});
    }
    parts.push_back({{"region", name}, {"levels", levels}});
  }
  return parts;
}

}  // namespace texsynth::cli
