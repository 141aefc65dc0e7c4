// Gradient solid synthesis driver: initialization, levels and iterations, final refinement (see
// gradient_synthesis.h).
#include "texsynth/gradient/gradient_synthesis.h"

#include <chrono>
#include <optional>

#include "synthesis_histogram.h"
#include "synthesis_refine.h"
#include "synthesis_sweep.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/core/timing.h"

namespace texsynth {
namespace {

using namespace gradient_synthesis;

void checkOptions(const std::vector<const GradientExemplars*>& sets, const GradientSynthesisOptions& o) {
  if (sets.empty()) throw ParameterError("exemplars", "give at least one exemplar set");
  for (const GradientExemplars* set : sets) {
    if (!set) throw ParameterError("exemplars", "an exemplar set is null");
    if (set->colorChannels() != sets[0]->colorChannels() || set->hasMask() != sets[0]->hasMask() ||
        set->options().levelSizes != sets[0]->options().levelSizes)
      throw ParameterError("exemplars", "the exemplar sets differ in channels, masks or levels");
  }
  for (int a = 0; a < 3; ++a)
    if (o.voxels[a] < 2 || o.voxels[a] > 8192)
      throw ParameterError("voxels", "must be in [2, 8192] per axis, got " + std::to_string(o.voxels[a]));
  if (o.spacing < 2 || o.spacing > 16 || o.spacing % 2)
    throw ParameterError("spacing", "must be even, in [2, 16], got " + std::to_string(o.spacing));
  if (o.iterations < 1 || o.iterations > 20)
    throw ParameterError("iterations", "must be in [1, 20], got " + std::to_string(o.iterations));
  if (o.checkPoints < 1 || o.checkPoints > 64)
    throw ParameterError("checkPoints", "must be in [1, 64], got " + std::to_string(o.checkPoints));
  if (o.matchedSlices != 2 && o.matchedSlices != 3)
    throw ParameterError("matchedSlices", "must be 2 or 3, got " + std::to_string(o.matchedSlices));
  if (o.candidatesY < 1 || o.candidatesY > 1000)
    throw ParameterError("candidatesY", "must be in [1, 1000], got " + std::to_string(o.candidatesY));
  if (o.candidatesZ < 1 || o.candidatesZ > 1000)
    throw ParameterError("candidatesZ", "must be in [1, 1000], got " + std::to_string(o.candidatesZ));
  if (o.optimizeIterations < 0 || o.optimizeIterations > 1000)
    throw ParameterError("optimizeIterations", "must be in [0, 1000]");
}

// §4.1: every control point a random exemplar pixel (the XY exemplar's finest level), gradients zero.
GradientSolid initialize(const std::vector<const GradientExemplars::Impl*>& sets, const GradientSynthesisOptions& o,
                         int features) {
  GradientSolid state = GradientSolid::zeros(o.voxels, features, o.spacing);
  const std::size_t setSize = std::size_t(state.setSize());
  parallelFor(0, state.controls.z(), [&](std::int64_t k) {
    for (int j = 0; j < state.controls.y(); ++j)
      for (int i = 0; i < state.controls.x(); ++i) {
        const Vec3f position =
            (float(o.spacing) * Vec3f(float(i), float(j), float(k))).cwiseMin((o.voxels - Vec3i::Ones()).cast<float>());
        const int set = o.exemplarSetOf ? o.exemplarSetOf(position) : 0;
        TS_CHECK_MSG(set >= 0 && set < int(sets.size()), "exemplar set rule out of range");
        const Image& image = sets[std::size_t(set)]
                                 ->at(SlicePlane::Z, int(sets[std::size_t(set)]->options.levelSizes.size()) - 1)
                                 .level->image;
        const std::uint64_t key = hashKey(o.seed, latticeId(i, j, k), 0xfeed);
        const std::uint32_t pixel = uniformBelow(key, std::uint32_t(image.pixelCount()));
        std::copy_n(&image.pixels[std::size_t(pixel) * features], features,
                    &state.positive[std::size_t(state.controlIndex(i, j, int(k))) * setSize]);
      }
  });
  return state;
}

// The colour channels of the feature-vector solid (the mask's feature channel dropped).
GradientSolid colorsOnly(const GradientSolid& state, int colors) {
  if (state.channels == colors) return state;
  GradientSolid out = GradientSolid::zeros(state.voxels, colors, state.spacing);
  for (std::int64_t c = 0; c < state.controlCount(); ++c)
    for (int slot = 0; slot < 4; ++slot)
      std::copy_n(&state.positive[std::size_t(c) * state.setSize() + std::size_t(slot) * state.channels], colors,
                  &out.positive[std::size_t(c) * out.setSize() + std::size_t(slot) * colors]);
  return out;
}

}  // namespace

GradientSolid synthesizeGradientSolid(const std::vector<const GradientExemplars*>& exemplarSets,
                                      const GradientSynthesisOptions& options, GradientSynthesisReport* report,
                                      Progress& progress) {
  checkOptions(exemplarSets, options);
  const auto start = std::chrono::steady_clock::now();
  GradientSynthesisReport local;
  LevelContext base;
  for (const GradientExemplars* set : exemplarSets) {
    base.sets.push_back(&set->impl());
    base.clusterOffset.push_back(base.clusterCount);
    base.clusterCount += set->impl().clusters.count;
  }
  if (base.clusterCount > 255) throw ParameterError("clusters", "more than 255 over all exemplar sets");
  base.options = &options;
  base.features = base.sets[0]->features;
  base.rotated = bool(options.orientation);
  const int colors = base.sets[0]->colorChannels;
  const int levels = exemplarSets[0]->levels();

  GradientSolid state = initialize(base.sets, options, base.features);
  local.initializeSeconds = secondsSince(start);

  const bool regions = options.regions && base.sets[0]->hasMask;
  const bool refine = regions || options.optimize || options.detail;
  std::optional<SlabRefiner> refiner;
  std::function<void(const ClosedLayer&)> closed;
  SweepStats stats;
  // One step per cube layer of every iteration of every level.
  progress.begin("gradient synthesis", std::int64_t(levels) * options.iterations * (state.controls.z() - 1));
  for (int level = 0; level < levels; ++level) {
    const auto levelStart = std::chrono::steady_clock::now();
    LevelContext ctx = base;
    ctx.level = level;
    ctx.spacing = 1 << (levels - 1 - level);
    ctx.size = exemplarSets[0]->options().levelSizes[std::size_t(level)];
    ctx.quantized = level == levels - 1;  // quantization at the finest level is enough (§4.2.2)
    for (int iteration = 0; iteration < options.iterations; ++iteration) {
      ctx.iteration = iteration;
      const bool last = level == levels - 1 && iteration == options.iterations - 1;
      if (last && refine) {
        VectorizeOptions vectorize;
        vectorize.spacing = options.spacing;
        vectorize.optimize = options.optimize;
        vectorize.iterations = options.optimizeIterations;
        vectorize.detail = options.detail;
        refiner.emplace(state, colors, regions, vectorize);
        closed = [&refiner](const ClosedLayer& layer) { refiner->take(layer); };
      }
      sweepIteration(ctx, state, stats, closed, progress);
      matchControlHistograms(state, base.sets[0]->at(SlicePlane::Z, level).level->image);
    }
    local.levelSeconds.push_back(secondsSince(levelStart));
  }
  progress.end();
  local.synthesisSeconds = secondsSince(start) - local.initializeSeconds;
  const auto refineStart = std::chrono::steady_clock::now();
  GradientSolid solid = refiner ? refiner->finish() : colorsOnly(state, colors);
  // The refinement fits the last buckets' averages: give its colours the exemplar's distribution too.
  if (refiner) matchControlHistograms(solid, base.sets[0]->at(SlicePlane::Z, levels - 1).level->image);
  local.refineSeconds = secondsSince(refineStart);
  local.checkPointsMatched = stats.checkPoints;
  local.peakBucketBytes = stats.peakBucketBytes + (refiner ? refiner->peakBytes() : 0);
  local.fullBucketBytes = std::int64_t(options.voxels.x()) * options.voxels.y() * options.voxels.z() *
                          std::int64_t(base.clusterCount + 2 + 4 * (base.features + 1));
  local.boundaryControls = std::int64_t(solid.negative.size()) / std::max(1, solid.setSize());
  local.totalSeconds = secondsSince(start);
  if (report) *report = local;
  return solid;
}

}  // namespace texsynth
