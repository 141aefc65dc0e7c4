// Flow animation on a mesh surface: frame 0 a static surface synthesis, every further frame
// advected over the finest level's triangles and repaired by the discrete solver
// (frame_solver.h) on its vertices.
#include "texsynth/animation/surface_animation.h"

#include <chrono>

#include "frame_solver.h"
#include "texsynth/core/error.h"
#include "texsynth/core/timing.h"
#include "texsynth/surface/surface_domain.h"

namespace texsynth {

SurfaceAnimator::SurfaceAnimator(std::span<const ExemplarAnalysis> analyses, const PreparedSurface& surface,
                                 const TextureOptimizationOptions& synthesis, const FlowAnimationOptions& options,
                                 Progress& progress)
    : analyses_(analyses),
      surface_(surface),
      synthesis_(synthesis),
      options_(options),
      projector_(surface.finestMesh()) {
  validateFlowAnimationOptions(options);
  const SurfaceSynthesisResult result = synthesizeSurface(analyses, surface, synthesis, progress);
  sources_ = result.sources;
  colors_ = result.colors;
  positions_ = ExemplarPositions::atPixels(sources_, analyses.back().width, analyses.back().height);
  statistics_.solveSeconds = statistics_.seconds = result.seconds;
}

void SurfaceAnimator::advance(std::span<const Vec3f> velocities, Progress& progress) {
  const Mesh& mesh = surface_.finestMesh();
  if (velocities.size() != mesh.positions.size())
    throw ParameterError("velocities", std::to_string(velocities.size()) + " velocities for " +
                                           std::to_string(mesh.positions.size()) + " vertices");
  const auto start = std::chrono::steady_clock::now();
  const ExemplarAnalysis& base = analyses_.back();
  ++frame_;
  statistics_ = FrameStatistics{};
  statistics_.frame = frame_;
  // The previous frame carried along the flow: its exemplar positions moved, their colors (what
  // pure advection would show, and E_c's u).
  const PreparedSurfaceLevel& finest = surface_.levels.back();
  positions_ = advectSurfacePositions(positions_, mesh, finest.tangents, surface_.hierarchy.levels.back().spacing,
                                      backtraceSurface(mesh, projector_, velocities));
  const std::vector<std::int32_t> advected = positions_.pixels;
  const std::vector<Vec3f> carried = colorsOfSources(base.levels.back().image, advected);
  statistics_.advectSeconds = secondsSince(start);
  const auto solveStart = std::chrono::steady_clock::now();
  if (options_.coherence == 0.0f) {  // independent frames
    TextureOptimizationOptions options = synthesis_;
    options.seed = hashKey(synthesis_.seed, std::uint64_t(frame_), 0xf4a3e);
    sources_ = synthesizeSurface(analyses_, surface_, options, progress).sources;
    positions_ = ExemplarPositions::atPixels(sources_, base.width, base.height);
  } else {
    std::vector<detail::SurfaceDomain> domains;
    for (const SurfaceNeighborhoods& neighborhoods : finest.neighborhoods)
      domains.push_back({neighborhoods, base.channels()});
    detail::FrameSolution solution =
        detail::solveFrame([&](std::size_t scale) -> const detail::SurfaceDomain& { return domains[scale]; }, analyses_,
                           synthesis_, options_, 0, advected, hashKey(synthesis_.seed, std::uint64_t(frame_)));
    positions_.keepWhereUnchanged(solution.sources);
    statistics_.energy = solution.energy;
    sources_ = std::move(solution.sources);
  }
  statistics_.solveSeconds = secondsSince(solveStart);
  statistics_.keptFraction = detail::keptFraction(advected, sources_);
  colors_ = colorsOfSources(base.levels.back().image, sources_);
  statistics_.temporalChange = meanColorChange(colors_, carried);
  statistics_.seconds = secondsSince(start);
}

}  // namespace texsynth
