// Flow animation on a toroidal image: frame 0 a static synthesis, every further frame advected
// and repaired by the discrete solver (frame_solver.h) on the finest level's grid.
#include "texsynth/animation/image_animation.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "frame_solver.h"
#include "texsynth/core/error.h"
#include "texsynth/core/timing.h"
#include "texsynth/image/optimization_grid.h"
#include "texsynth/image/parallel_synthesis.h"

namespace texsynth {
namespace {

// Frame neighborhoods' centre spacing: N / divisor, lowered until it divides both sides.
int frameStride(int size, int divisor, int width, int height) {
  int stride = std::max(1, size / std::max(1, divisor));
  while (width % stride != 0 || height % stride != 0) --stride;
  return stride;
}

}  // namespace

ImageAnimator::ImageAnimator(std::span<const ExemplarAnalysis> analyses, const ExemplarAnalysis* parallelAnalysis,
                             const TextureOptimizationOptions& synthesis, const FlowAnimationOptions& options,
                             int width, int height, Progress& progress)
    : analyses_(analyses),
      parallelAnalysis_(parallelAnalysis),
      synthesis_(synthesis),
      options_(options),
      width_(width),
      height_(height) {
  validateFlowAnimationOptions(options);
  if (synthesis.solver != OptimizationSolver::Discrete)
    throw ParameterError("solver", "flow animation needs the discrete solver (least squares keeps no sources)");
  for (const auto& [name, side] : {std::pair{"width", width}, std::pair{"height", height}})
    if (side <= 0 || side % 4 != 0)
      throw ParameterError(name,
                           "must be a positive multiple of 4 (the animated texture is a torus of whole "
                           "neighborhood strides), got " +
                               std::to_string(side));
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::int32_t> sources = staticSynthesis(synthesis.seed, progress);
  positions_ = ExemplarPositions::atPixels(sources, analyses.back().width, analyses.back().height);
  colors_ = colorsOf(sources);
  statistics_.solveSeconds = statistics_.seconds = secondsSince(start);
}

std::vector<std::int32_t> ImageAnimator::staticSynthesis(std::uint64_t seed, Progress& progress) const {
  TextureOptimizationOptions options = synthesis_;
  options.seed = seed;
  std::optional<SourceCoordinates> start;
  if (parallelAnalysis_) {
    ParallelSynthesisOptions parallel;
    parallel.seed = seed;
    start = parallelOptimizationStart(*parallelAnalysis_, parallel, analyses_, options, width_, height_, progress);
  }
  const TextureOptimizationResult result =
      optimizeTexture(analyses_, options, width_, height_, progress, start ? &*start : nullptr);
  return result.coords.pixelIndices(analyses_.back().width);
}

Image ImageAnimator::colorsOf(std::span<const std::int32_t> sources) const {
  const ExemplarAnalysis& base = analyses_.back();
  const Image& exemplar = base.levels.back().image;
  Image colors(width_, height_, base.colorChannels);
  for (std::size_t i = 0; i < sources.size(); ++i)
    std::copy_n(exemplar.pixels.data() + std::size_t(sources[i]) * exemplar.channels, base.colorChannels,
                colors.pixels.data() + i * std::size_t(base.colorChannels));
  return colors;
}

void ImageAnimator::advance(const Image& velocities, Progress& progress) {
  if (velocities.width != width_ || velocities.height != height_ || velocities.channels < 2)
    throw ParameterError("velocities", std::to_string(velocities.width) + "x" + std::to_string(velocities.height) +
                                           " velocities for a " + std::to_string(width_) + "x" +
                                           std::to_string(height_) + " animation");
  const auto start = std::chrono::steady_clock::now();
  ++frame_;
  statistics_ = FrameStatistics{};
  statistics_.frame = frame_;
  // The previous frame carried along the flow: its exemplar positions moved, their colors (what
  // pure advection would show, and E_c's u).
  positions_ = advectImagePositions(positions_, backtraceImage(velocities), width_);
  const std::vector<std::int32_t> advected = positions_.pixels;
  const Image carried = colorsOf(advected);
  statistics_.advectSeconds = secondsSince(start);
  const auto solveStart = std::chrono::steady_clock::now();
  std::vector<std::int32_t> sources;
  if (options_.coherence == 0.0f) {  // independent frames
    sources = staticSynthesis(hashKey(synthesis_.seed, std::uint64_t(frame_), 0xf4a3e), progress);
    positions_ = ExemplarPositions::atPixels(sources, analyses_.back().width, analyses_.back().height);
  } else {
    const ExemplarAnalysis& base = analyses_.back();
    std::vector<detail::OptimizationGrid> grids;
    for (int size : synthesis_.neighborhoodSizes)
      grids.emplace_back(base, base.levelCount() - 1, width_, height_, size, detail::PixelNorm::Squared,
                         frameStride(size, options_.frameStrideDivisor, width_, height_));
    // The centres' lattice moves from frame to frame, so that patch seams do not stay put.
    const std::uint64_t key = hashKey(synthesis_.seed, std::uint64_t(frame_), 0x0ff5e7);
    for (detail::OptimizationGrid& grid : grids) {
      grid.offsetX = int(uniformBelow(key, std::uint32_t(grid.stride)));
      grid.offsetY = int(uniformBelow(mix64(key), std::uint32_t(grid.stride)));
    }
    detail::FrameSolution solution = detail::solveFrame(
        [&](std::size_t scale) -> const detail::OptimizationGrid& { return grids[scale]; }, analyses_, synthesis_,
        options_, 0, advected, hashKey(synthesis_.seed, std::uint64_t(frame_)));
    positions_.keepWhereUnchanged(solution.sources);
    statistics_.energy = solution.energy;
    sources = std::move(solution.sources);
  }
  statistics_.solveSeconds = secondsSince(solveStart);
  statistics_.keptFraction = detail::keptFraction(advected, sources);
  colors_ = colorsOf(sources);
  statistics_.temporalChange = meanColorChange(colors_, carried);
  statistics_.seconds = secondsSince(start);
}

}  // namespace texsynth
