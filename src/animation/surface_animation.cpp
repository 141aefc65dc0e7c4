// Flow animation on a mesh surface: frame 0 a static surface synthesis, every further frame
// advected over the finest level's triangles and repaired by the discrete solver
// (frame_solver.h) on its vertices, or by the surface start's correction where the solver would
// make the frame flat.
#include "texsynth/animation/surface_animation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "frame_solver.h"
#include "texsynth/core/error.h"
#include "texsynth/core/timing.h"
#include "texsynth/surface/surface_domain.h"
#include "texsynth/surface/surface_level_measures.h"
#include "texsynth/surface/surface_parallel.h"

namespace texsynth {
namespace {

// Continuous coordinates as exemplar positions (the nearest pixel and the rest), and back.
ExemplarPositions positionsOf(std::span<const Vec2f> coordinates, int width, int height) {
  ExemplarPositions positions{width, height, pixelsOfCoordinates(coordinates, width, height),
                              std::vector<Vec2f>(coordinates.size())};
  for (std::size_t v = 0; v < coordinates.size(); ++v)
    positions.offsets[v] =
        Vec2f(coordinates[v].x() - std::round(coordinates[v].x()), coordinates[v].y() - std::round(coordinates[v].y()));
  return positions;
}

std::vector<Vec2f> coordinatesOf(const ExemplarPositions& positions) {
  std::vector<Vec2f> coordinates = coordinatesOfPixels(positions.pixels, positions.exemplarWidth);
  for (std::size_t v = 0; v < coordinates.size(); ++v) coordinates[v] += positions.offsets[v];
  return coordinates;
}

}  // namespace

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
  reference_ = measureSurfaceLevel(surface.levels.back().stencil, analyses.back().levels.back(), result.coordinates);
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
    statistics_.energy = solution.energy;
    // The discrete solver repairs from whole-pixel sources, and frame after frame that can wash the
    // texture out (GIMP brick on the CGAL bunny, 12 frames along the field: flatness -0.05 to
    // 0.23). Where its frame is flatter than frame 0 or has lost the exemplar's distinctive
    // colors, the advected frame is repaired by the start's correction instead (surface_parallel.h).
    const ExemplarLevel& finestStack = base.levels.back();
    const SurfaceLevelMeasures solved =
        measureSurfaceLevel(finest.stencil, finestStack, coordinatesOfPixels(solution.sources, base.width));
    statistics_.solverKept = keepsTheFeatures(reference_, solved);
    if (statistics_.solverKept) {
      positions_.keepWhereUnchanged(solution.sources);
      sources_ = std::move(solution.sources);
    } else {
      std::vector<Vec2f> coordinates = coordinatesOf(positions_);
      SurfaceParallelOptions correction;
      correction.seed = hashKey(synthesis_.seed, std::uint64_t(frame_), 0xc0e7);
      // No usage term: it moves coherent vertices too, and the frames flicker (brick on the bunny,
      // 12 frames along the field: usage 0 keeps 46% of the advected sources, temporal change 9.0;
      // usage 2: 21%, 17.4; the solver alone 24%, 9.6, and flatness 0.23 at the last frame
      // against 0.13 here).
      correction.usageWeight = 0;
      correctSurfaceCoordinates(finest.stencil, base, base.levelCount() - 1, correction, coordinates);
      positions_ = positionsOf(coordinates, base.width, base.height);
      sources_ = positions_.pixels;
    }
  }
  statistics_.solveSeconds = secondsSince(solveStart);
  statistics_.keptFraction = detail::keptFraction(advected, sources_);
  colors_ = colorsOfSources(base.levels.back().image, sources_);
  statistics_.temporalChange = meanColorChange(colors_, carried);
  statistics_.seconds = secondsSince(start);
}

}  // namespace texsynth
