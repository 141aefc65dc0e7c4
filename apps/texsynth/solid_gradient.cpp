// texsynth solid --method gradient: gradient solid synthesis from image exemplars (the library's
// gradient_synthesis.h), with a field, a mask and regions as the command line asks.
#include <cmath>

#include "solid_args.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/field/field_designer.h"
#include "texsynth/field/field_io.h"
#include "texsynth/field/sketch.h"
#include "texsynth/gradient/gradient_solid_texture.h"
#include "texsynth/gradient/gradient_synthesis.h"
#include "texsynth/io/image_io.h"
#include "texsynth/solid/region_solid.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

// Peak bytes of a synthesis: the control points (feature vectors of up to 4 channels as floats, with a layer's
// work copies) and the bucket window, about 2.3 KB per voxel column at the finest level (588 MiB for 512² columns,
// bench/gradient_synthesis.sh; a field widens the window by sqrt 2).
double synthesisBytes(const Vec3i& voxels, bool rotated) {
  const double controls = double(voxels.x() / 4 + 2) * double(voxels.y() / 4 + 2) * double(voxels.z() / 4 + 2);
  const double column = rotated ? 3300.0 : 2400.0;
  return controls * 96.0 + double(voxels.x()) * voxels.y() * column + 100e6;
}

}  // namespace

std::shared_ptr<const GradientSolid> synthesizeGradient(const SolidArgs& args, const Mesh& mesh, const Box3f& box,
                                                        std::uint64_t seed, const GlobalOptions& globals,
                                                        json& report) {
  if (args.exemplars.size() == 2)
    throw ParameterError("EXEMPLAR", "give one exemplar for all three planes, or three: XY YZ ZX");
  GradientSynthesisOptions options;
  for (int a = 0; a < 3; ++a)
    options.voxels[a] = std::max(2, int(std::ceil(double(args.resolution) * box.size()[a] / box.size().maxCoeff())));
  options.iterations = args.iterations;
  options.checkPoints = args.checkPoints;
  options.matchedSlices = args.matchedSlices;
  options.crossbar = args.crossbar;
  options.regions = args.regions;
  options.optimize = args.optimize;
  options.detail = args.detail == "on";
  options.seed = seed;
  // Voxel units -> world: the solid spans the box.
  const float voxelsPerUnit = float(options.voxels.maxCoeff() - 1) / box.size().maxCoeff();
  const Vec3f origin = box.min;
  auto world = [origin, voxelsPerUnit](const Vec3f& voxel) { return origin + voxel / voxelsPerUnit; };
  std::shared_ptr<const RotationField> field;
  if (!args.field.empty()) {
    field = std::make_shared<const RotationField>(readField(args.field).rotations);
    report["field"] = args.field;
  } else if (!args.sketch.empty()) {
    if (mesh.positions.empty()) throw ParameterError("--sketch", "needs --mesh: the field is designed around it");
    field = std::make_shared<const RotationField>(
        designField(mesh, readSketch(args.sketch), {}, noProgress(), args.sketch).rotations);
    report["sketch"] = args.sketch;
  }
  if (field) options.orientation = [field, world](const Vec3f& voxel) { return field->sample(world(voxel)); };
  requireMemory(synthesisBytes(options.voxels, bool(field)), "--resolution",
                "a gradient solid synthesis of " + std::to_string(options.voxels.x()) + "x" +
                    std::to_string(options.voxels.y()) + "x" + std::to_string(options.voxels.z()) + " voxels");

  GradientExemplarOptions exemplarOptions;
  exemplarOptions.clusters = args.clusters;
  exemplarOptions.cacheDirectory = defaultCacheDirectory();
  auto progress = makeProgress(globals);
  const auto started = std::chrono::steady_clock::now();
  std::vector<std::unique_ptr<GradientExemplars>> sets;
  sets.push_back(std::make_unique<GradientExemplars>(readImages(args.exemplars), readImages(args.masks),
                                                     exemplarOptions, *progress));
  if (!args.inner.empty()) {
    if (mesh.positions.empty())
      throw ParameterError("--inner", "needs --mesh: the regions are depths below its surface");
    if (!args.masks.empty())
      throw ParameterError("--inner",
                           "with --mask: the mask describes the outer exemplars only; give neither or "
                           "synthesize the regions separately");
    sets.push_back(std::make_unique<GradientExemplars>(std::vector<Image>{readImage(args.inner)}, std::vector<Image>{},
                                                       exemplarOptions, *progress));
    const float depth = args.shell * mesh.bounds().size().norm();
    report["shell_depth"] = depth;
    auto rule = std::make_shared<RegionSolidTexture::RegionRule>(surfaceShellRule(mesh, depth));
    options.exemplarSetOf = [rule, world](const Vec3f& voxel) { return (*rule)(world(voxel)); };
  }
  report["exemplar_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::vector<const GradientExemplars*> pointers;
  for (const auto& set : sets) pointers.push_back(set.get());
  GradientSynthesisReport synthesis;
  auto solid = std::make_shared<const GradientSolid>(synthesizeGradientSolid(pointers, options, &synthesis, *progress));
  report["variant"] = field ? "gradient synthesis, guided by a field" : "gradient synthesis";
  report["synthesis"] = {{"voxels", {options.voxels.x(), options.voxels.y(), options.voxels.z()}},
                         {"controls", {solid->controls.x(), solid->controls.y(), solid->controls.z()}},
                         {"seconds", synthesis.totalSeconds},
                         {"level_seconds", synthesis.levelSeconds},
                         {"check_points", synthesis.checkPointsMatched},
                         {"bucket_window_mib", double(synthesis.peakBucketBytes) / (1 << 20)},
                         {"full_buckets_mib", double(synthesis.fullBucketBytes) / (1 << 20)},
                         {"boundary_controls", synthesis.boundaryControls}};
  return solid;
}

}  // namespace texsynth::cli
