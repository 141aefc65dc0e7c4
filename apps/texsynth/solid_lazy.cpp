// texsynth solid --method lazy: the lazy recipe from the flags (options, masks, field, regions)
// and a report of its work.
#include "solid_args.h"
#include "texsynth/field/field_designer.h"
#include "texsynth/field/field_io.h"
#include "texsynth/field/sketch.h"
#include "texsynth/io/image_io.h"

namespace texsynth::cli {

using nlohmann::json;

void fillLazyRecipe(const SolidArgs& args, const Mesh& mesh, SolidRecipe& recipe, json& report) {
  LazySolidOptions& options = recipe.lazy;
  options.levels = args.levels;  // 0: as many as the exemplar allows
  options.passes = args.passes;
  options.coarsestPasses = args.coarsestPasses;
  options.dualGrid = args.dualGrid;
  options.gridCellSize = args.gridCell;
  options.subpassGrid = args.subpasses;
  options.candidateCount = args.candidates;
  options.colorRule =
      args.colorRule == "mean" ? LazySolidOptions::ColorRule::Mean : LazySolidOptions::ColorRule::Medoid;
  options.cacheDirectory = defaultCacheDirectory();
  if (!args.masks.empty() && args.masks.size() != 1 && args.masks.size() != args.exemplars.size())
    throw ParameterError("--mask", "give one mask for all planes, or one per exemplar (XY YZ ZX)");
  options.featureMasks = readImages(args.masks);
  if (!args.field.empty()) {
    recipe.field = std::make_shared<const RotationField>(readField(args.field).rotations);
    report["field"] = args.field;
  } else if (!args.sketch.empty()) {
    if (mesh.positions.empty()) throw ParameterError("--sketch", "needs --mesh: the field is designed around it");
    recipe.field = std::make_shared<const RotationField>(
        designField(mesh, readSketch(args.sketch), {}, noProgress(), args.sketch).rotations);
    report["sketch"] = args.sketch;
  }
  report["variant"] = !args.field.empty()    ? "lazy, guided by --field"
                      : !args.sketch.empty() ? "lazy, guided by the field of --sketch"
                                             : "lazy, identity field";
  if (args.inner.empty()) return;
  if (mesh.positions.empty()) throw ParameterError("--inner", "needs --mesh: the regions are depths below its surface");
  recipe.inner = readImage(args.inner);
  recipe.mesh = &mesh;
  recipe.shellDepth = args.shell * mesh.bounds().size().norm();
  report["shell_depth"] = recipe.shellDepth;
}

json lazyStats(const SolidBuild& build) {
  json parts = json::array();
  for (const auto& [name, synthesis] : build.lazyParts) {
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
