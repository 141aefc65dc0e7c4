#include "texsynth/gradient/vectorize.h"

#include <chrono>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/timing.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "vectorize_layout.h"
#include "vectorize_regions.h"

namespace texsynth {
namespace {

using namespace vectorize_detail;

// The colour channels vectorized: gray or RGB (alpha is dropped).
Volume colorChannels(const Volume& volume) {
  const int keep = volume.channels >= 3 ? 3 : 1;
  if (keep == volume.channels) return volume;
  Volume colors(volume.nx, volume.ny, volume.nz, keep);
  for (std::size_t v = 0; v < volume.voxelCount(); ++v)
    for (int c = 0; c < keep; ++c) colors.voxels[v * keep + c] = volume.voxels[v * volume.channels + c];
  return colors;
}

void checkInput(const Volume& volume, const Volume& mask, const VectorizeOptions& options) {
  if (volume.empty()) throw ParameterError("volume", "is empty");
  for (float v : volume.voxels)
    if (!std::isfinite(v)) throw ParameterError("volume", "holds a non-finite voxel value");
  if (!mask.empty()) {
    if (mask.nx != volume.nx || mask.ny != volume.ny || mask.nz != volume.nz)
      throw ParameterError("mask", "is " + std::to_string(mask.nx) + "x" + std::to_string(mask.ny) + "x" +
                                       std::to_string(mask.nz) + ", the volume " + std::to_string(volume.nx) + "x" +
                                       std::to_string(volume.ny) + "x" + std::to_string(volume.nz));
    if (mask.channels != 1) throw ParameterError("mask", "must have one channel (> 0.5 inside)");
  }
  if (options.spacing < 1 || options.spacing > 64)
    throw ParameterError("spacing", "must be in [1, 64], got " + std::to_string(options.spacing));
  if (options.iterations < 0 || options.iterations > 1000)
    throw ParameterError("iterations", "must be in [0, 1000], got " + std::to_string(options.iterations));
}

// Fits one layout's sets: eq. 2, then eq. 3 when asked.
std::vector<float> fitSets(const FitLayout& layout, const FitTargets& targets, const VectorizeOptions& options,
                           double& optimizeSeconds) {
  std::vector<float> sets;
  fitFirstOrder(layout, targets, sets);
  if (options.optimize) {
    const auto start = std::chrono::steady_clock::now();
    refineControlPoints(layout, targets, options.iterations, sets);
    optimizeSeconds += secondsSince(start);
  }
  return sets;
}

// §5.4: sigma per channel, the root of the local mean squared residual, itself a gradient-solid channel.
std::vector<float> fitDetail(const GradientSolid& solid, const Volume& colors, const FitLayout& plain) {
  Volume squared = rasterizeGradientSolid(solid);
  for (std::size_t n = 0; n < squared.voxels.size(); ++n) {
    const float r = colors.voxels[n] - squared.voxels[n];
    squared.voxels[n] = r * r;
  }
  FitTargets targets;
  targets.original = &squared;
  std::vector<float> sets;
  fitFirstOrder(plain, targets, sets);
  const int channels = solid.channels;
  for (std::size_t base = 0; base < sets.size(); base += 4 * std::size_t(channels))
    for (int c = 0; c < channels; ++c) {
      const float variance = sets[base + c], sigma = std::sqrt(std::max(variance, 0.0f));
      sets[base + c] = sigma;
      for (int slot = 1; slot < 4; ++slot) {  // d sigma = d variance / (2 sigma)
        float& g = sets[base + slot * channels + c];
        g = sigma > 1e-4f ? g / (2.0f * sigma) : 0.0f;
      }
    }
  return sets;
}

// 1 where the solid's distance puts a voxel on the positive side (as evaluation decides), else 0.
Volume evaluatedSides(const GradientSolid& solid) {
  Volume sides(solid.voxels.x(), solid.voxels.y(), solid.voxels.z(), 1);
  parallelFor(0, sides.nz, [&](std::int64_t z) {
    for (int y = 0; y < sides.ny; ++y)
      for (int x = 0; x < sides.nx; ++x)
        sides.at(x, y, int(z), 0) =
            evaluateGradientDistance(solid, Vec3f(float(x), float(y), float(z))) >= 0.0f ? 1.0f : 0.0f;
  });
  return sides;
}

}  // namespace

GradientSolid vectorizeVolume(const Volume& volume, const Volume& mask, const VectorizeOptions& options,
                              VectorizeReport* report, Progress& progress) {
  checkInput(volume, mask, options);
  const auto start = std::chrono::steady_clock::now();
  const Volume colors = colorChannels(volume);
  GradientSolid solid = GradientSolid::zeros({volume.nx, volume.ny, volume.nz}, colors.channels, options.spacing);
  const ControlGrid grid{solid.voxels, solid.controls, solid.spacing};
  const std::size_t controls = std::size_t(solid.controlCount()), setSize = std::size_t(solid.setSize());
  VectorizeReport local;
  progress.begin("vectorize", 3 + (options.detail ? 1 : 0));

  FitLayout plain{grid, colors.channels, {}, nullptr, 0};
  FitTargets targets;
  targets.original = &colors;
  if (mask.empty()) {
    solid.positive = fitSets(plain, targets, options, local.optimizeSeconds);
    progress.advance(2);
  } else {
    // The distance first, always refined by eq. 3: a voxel on the wrong side costs a whole colour jump, and
    // one channel is cheap next to the colours. Kept to 3 cubes: enough for the sign near the boundary.
    const Volume signedDistance = signedDistanceVolume(mask, 3.0f * float(options.spacing));
    FitLayout distanceLayout{grid, 1, {}, nullptr, 0};
    FitTargets distanceTargets;
    distanceTargets.original = &signedDistance;
    VectorizeOptions distanceOptions = options;
    distanceOptions.optimize = true;
    double distanceSeconds = 0;
    solid.distance = fitSets(distanceLayout, distanceTargets, distanceOptions, distanceSeconds);
    solid.negativeIndex.assign(controls, -1);
    if (options.quantize) quantizeGradientSolid(solid);  // the distance as stored decides the sides
    // The colours are fitted to the regions evaluation will use: the sides of the fitted distance, which
    // differ from the mask's at a few voxels along the boundary.
    const Volume sides = evaluatedSides(solid);
    const Regions regions = separateRegions(grid, colors, sides);
    progress.advance(1);
    FitLayout separated{grid, colors.channels, regions.cubeSides, &regions.negativeIndex, regions.negatives};
    targets.positive = &regions.positive;
    targets.negative = &regions.negative;
    targets.sides = &sides;
    std::vector<float> sets = fitSets(separated, targets, options, local.optimizeSeconds);
    solid.positive.assign(sets.begin(), sets.begin() + std::ptrdiff_t(controls * setSize));
    solid.negative.assign(sets.begin() + std::ptrdiff_t(controls * setSize), sets.end());
    solid.negativeIndex = regions.negativeIndex;
    local.boundaryControls = regions.negatives;
    progress.advance(1);
  }
  if (options.quantize) quantizeGradientSolid(solid);
  progress.advance(1);
  local.fitSeconds = secondsSince(start) - local.optimizeSeconds;
  if (options.detail) {
    solid.detail = fitDetail(solid, colors, plain);
    if (options.quantize) quantizeGradientSolid(solid);
    progress.advance(1);
  }
  solid.checkConsistent();
  local.totalSeconds = secondsSince(start);
  local.rms = gradientSolidRms(solid, colors);
  progress.end();
  if (report) *report = local;
  return solid;
}

}  // namespace texsynth
