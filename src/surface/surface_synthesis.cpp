// Surface synthesis driver: coarse to fine over the mesh hierarchy, at every level the parallel
// start and then the E+M refinement on continuous coordinates, at the finest a polish too, each
// kept where it does no harm.
#include "texsynth/surface/surface_synthesis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/core/timing.h"
#include "texsynth/image/discrete_steps.h"
#include "texsynth/surface/surface_level_measures.h"
#include "texsynth/surface/surface_optimization.h"
#include "texsynth/surface/surface_parallel.h"

namespace texsynth {
namespace {

using detail::ExemplarWindow;

void validate(std::span<const ExemplarAnalysis> analyses, const PreparedSurface& surface,
              const TextureOptimizationOptions& options) {
  if (options.solver != OptimizationSolver::Discrete)
    throw ParameterError("solver", "surface synthesis needs the discrete solver (least squares keeps no sources)");
  if (options.neighborhoodSizes != surface.neighborhoodSizes)
    throw ParameterError("neighborhood", "sizes differ from the ones the surface was prepared for");
  if (surface.levels.size() != surface.hierarchy.levels.size() || surface.levels.empty())
    throw ParameterError("surface", "is not prepared (prepareSurface)");
  const std::vector<AnalysisOptions> wanted = optimizationAnalysisOptions(options);
  if (analyses.size() != wanted.size())
    throw ParameterError(
        "analyses", "expected " + std::to_string(wanted.size()) + " analyses, got " + std::to_string(analyses.size()));
  for (std::size_t i = 0; i < analyses.size(); ++i) {
    const ExemplarAnalysis& a = analyses[i];
    if (a.levelCount() != int(surface.levels.size()) || a.neighborhoodSize != wanted[i].neighborhoodSize ||
        a.similarCount < wanted[i].similarCount || a.width != analyses[0].width || a.height != analyses[0].height)
      throw ParameterError("analyses", "analysis " + std::to_string(i) + " does not match the options (" +
                                           std::to_string(surface.levels.size()) +
                                           " levels as the mesh hierarchy, N, k, one exemplar)");
  }
}

}  // namespace

namespace {

// Measures a candidate for a level's state (its E+M refinement or its polish) and, unless
// `stateMeasures` already holds them, the state; the candidate replaces the state when it keeps the
// texture (surface_level_measures.h). `stateMeasures` ends holding the measures of the state kept,
// so the level's next refinement does not measure it again.
SurfaceRefinement keepUnlessHarmful(SurfaceRefinementStep step, const SurfaceStencil& stencil,
                                    const ExemplarLevel& stack, int level, std::vector<Vec2f>& state,
                                    std::optional<SurfaceLevelMeasures>& stateMeasures, std::vector<Vec2f>& candidate) {
  if (!stateMeasures) stateMeasures = measureSurfaceLevel(stencil, stack, state);
  const SurfaceLevelMeasures before = *stateMeasures;
  const SurfaceLevelMeasures after = measureSurfaceLevel(stencil, stack, candidate);
  const bool kept = keepsTheTexture(before, after);
  if (kept) {
    state.swap(candidate);
    stateMeasures = after;
  }
  return {level, step, before, after, kept};
}

}  // namespace

std::vector<AnalysisOptions> surfaceAnalysisOptions(const Image& exemplar, const TextureOptimizationOptions& options,
                                                    float featureWeight) {
  return withFeatureChannel(optimizationAnalysisOptions(options), exemplar, featureWeight);
}

SurfaceSynthesisResult synthesizeSurface(std::span<const ExemplarAnalysis> analyses, const PreparedSurface& surface,
                                         const TextureOptimizationOptions& options, Progress& progress,
                                         const SurfaceStartOptions& startOptions) {
  validate(analyses, surface, options);
  const auto start = std::chrono::steady_clock::now();
  const ExemplarAnalysis& base = analyses.back();
  const int levels = int(surface.levels.size());
  const int largest = *std::max_element(options.neighborhoodSizes.begin(), options.neighborhoodSizes.end());
  SurfaceSynthesisResult result;
  // The E+M refinement, as in 2D, only at levels whose largest neighborhood fits inside the
  // exemplar (there a tiled copy of it is a zero-energy optimum).
  int first = 0;
  while (first + 1 < levels && !ExemplarWindow(base, first, largest).bounded) ++first;
  result.firstLevel = first;
  SurfaceParallelOptions parallel = startOptions.parallel;
  parallel.seed = options.seed;
  const int refineSteps = int(options.neighborhoodSizes.size()) * (options.maxIterations + 1);
  std::vector<Vec2f> coordinates;
  for (int level = 0; level < levels; ++level) {
    const MeshLevel& mesh = surface.hierarchy.levels[std::size_t(level)];
    const PreparedSurfaceLevel& prepared = surface.levels[std::size_t(level)];
    const int passes = level == 0 ? std::max(parallel.passes, parallel.startPasses) : parallel.passes;
    const bool refine = startOptions.refine && level >= first;
    const bool finest = level + 1 == levels;
    const int polishes = finest ? startOptions.finestPolishPasses : 0;
    progress.begin("surface level " + std::to_string(level + 1) + "/" + std::to_string(levels) + " (" +
                       std::to_string(mesh.mesh.vertexCount()) + " vertices)",
                   passes + (refine ? refineSteps : 0) + polishes);
    const int h = base.levels[std::size_t(level)].spacing;
    if (level == 0) {
      coordinates = patchSurfaceCoordinates(prepared.neighborhoods[0], options.seed, level, h, base.width, base.height);
    } else {
      const PreparedSurfaceLevel& coarse = surface.levels[std::size_t(level - 1)];
      coordinates = upsampleSurfaceCoordinates(coarse.geometry, coarse.tangents, mesh, prepared.geometry, coordinates,
                                               float(h) / mesh.spacing, base.width, base.height);
      jitterSurfaceCoordinates(coordinates, level, h, parallel.jitter, options.seed, base.width, base.height);
    }
    SurfaceParallelOptions levelOptions = parallel;
    levelOptions.holdUsagePaidMoves = finest && startOptions.finestHoldsUsagePaidMoves;
    for (int pass = 0; pass < passes; ++pass) {
      // The histogram band in the last pass only: each banded pass may trade up to the band's
      // share of coherence, and on a smooth exemplar two of them leave no coherent copy.
      levelOptions.histogramBand = finest && pass + 1 == passes ? startOptions.finestHistogramBand : 0.0f;
      correctSurfaceCoordinates(prepared.stencil, base, level, levelOptions, coordinates);
      progress.advance(1);
    }
    const ExemplarLevel& stack = base.levels[std::size_t(level)];
    std::optional<SurfaceLevelMeasures> measures;  // of `coordinates`, once a refinement has measured them
    if (refine) {
      // The discrete optimization on top; its result replaces the start where it keeps the texture.
      std::vector<Vec2f> refined = coordinates;
      std::vector<OptimizationIteration> history;
      for (std::size_t scale = 0; scale < options.neighborhoodSizes.size(); ++scale)
        optimizeSurfaceCoordinates(prepared.neighborhoods[scale], base, level, scale, options, refined, history,
                                   progress, finest ? startOptions.finestRefineHistogramWeight : 0.0f);
      result.levels.push_back(keepUnlessHarmful(SurfaceRefinementStep::Optimization, prepared.stencil, stack, level,
                                                coordinates, measures, refined));
      result.history.insert(result.history.end(), history.begin(), history.end());
    }
    if (polishes > 0) {
      // The polish (SurfaceStartOptions): correction without the usage term, under the same rule.
      SurfaceParallelOptions polish = levelOptions;
      polish.usageWeight = 0;
      polish.histogramBand = startOptions.finestHistogramBand;
      std::vector<Vec2f> polished = coordinates;
      for (int pass = 0; pass < polishes; ++pass) {
        correctSurfaceCoordinates(prepared.stencil, base, level, polish, polished);
        progress.advance(1);
      }
      result.levels.push_back(keepUnlessHarmful(SurfaceRefinementStep::Polish, prepared.stencil, stack, level,
                                                coordinates, measures, polished));
    }
    progress.end();
  }
  result.sources = pixelsOfCoordinates(coordinates, base.width, base.height);
  const std::vector<float> colors = colorsAtCoordinates(base.levels.back().image, coordinates);
  const int c = base.levels.back().image.channels, color = base.colorChannels;
  result.colors.resize(coordinates.size());
  for (std::size_t v = 0; v < coordinates.size(); ++v) {
    const float* p = colors.data() + v * std::size_t(c);
    result.colors[v] = color >= 3 ? Vec3f(p[0], p[1], p[2]) : Vec3f::Constant(p[0]);
  }
  result.coordinates = std::move(coordinates);
  result.seconds = secondsSince(start);
  return result;
}

std::vector<Vec3f> colorsOfSources(const Image& image, std::span<const std::int32_t> sources) {
  const std::int64_t pixels = std::int64_t(image.width) * image.height;
  std::vector<Vec3f> colors(sources.size());
  const int c = image.channels;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (sources[i] < 0 || sources[i] >= pixels)
      throw ParameterError("sources", "entry " + std::to_string(i) + " (" + std::to_string(sources[i]) +
                                          ") lies outside the " + std::to_string(image.width) + "x" +
                                          std::to_string(image.height) + " image");
    const float* p = image.pixels.data() + std::size_t(sources[i]) * c;
    colors[i] = c >= 3 ? Vec3f(p[0], p[1], p[2]) : Vec3f::Constant(p[0]);
  }
  return colors;
}

}  // namespace texsynth
