// Texture optimization driver: coarse-to-fine over the exemplar's stack levels, at each level
// the neighborhood sizes in turn, at each size E+M iterations until the matches settle.
#include "texsynth/image/texture_optimization.h"

#include <algorithm>
#include <cmath>

#include "optimization_steps.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/exemplar/distinctive_colors.h"
#include "texsynth/image/flat_patch_share.h"
#include "texsynth/image/seam_blend.h"

namespace texsynth {
namespace {

using detail::Matches;
using detail::OptimizationGrid;

bool isLeastSquares(const TextureOptimizationOptions& options) {
  return options.solver == OptimizationSolver::LeastSquares;
}

void validate(const TextureOptimizationOptions& options) {
  if (options.levels < 0 || options.levels > 12)
    throw ParameterError(
        "levels", "must be in 0..12 (0 = as many as the exemplar allows), got " + std::to_string(options.levels));
  if (options.neighborhoodSizes.empty()) throw ParameterError("neighborhood", "needs at least one size");
  for (int n : options.neighborhoodSizes)
    if (n < 3 || n % 2 == 0 || n > kMaxNeighborhoodSize)
      throw ParameterError("neighborhood", "sizes must be odd and in 3.." + std::to_string(kMaxNeighborhoodSize) +
                                               ", got " + std::to_string(n));
  if (options.maxIterations < 1)
    throw ParameterError("iterations", "must be >= 1, got " + std::to_string(options.maxIterations));
  if (options.finestIterations < 1)
    throw ParameterError("finestIterations", "must be >= 1, got " + std::to_string(options.finestIterations));
  if (options.similarCount < 1)
    throw ParameterError("similarCount", "must be >= 1, got " + std::to_string(options.similarCount));
  if (!(options.coverageWeight >= 0.0f && options.coverageWeight <= 100.0f))
    throw ParameterError("coverageWeight", "must be in [0, 100], got " + std::to_string(options.coverageWeight));
  if (!(options.voteExponent >= 0.0f && options.voteExponent <= 16.0f))
    throw ParameterError("voteExponent", "must be in [0, 16], got " + std::to_string(options.voteExponent));
  if (options.randomCandidates < 0 || options.randomCandidates > 1024)
    throw ParameterError("randomCandidates", "must be in 0..1024, got " + std::to_string(options.randomCandidates));
  if (!(options.robustExponent > 0.0f && options.robustExponent <= 2.0f))
    throw ParameterError("robustExponent", "must be in (0, 2], got " + std::to_string(options.robustExponent));
  if (!(options.seamBlend >= 0.0f && options.seamBlend <= kMaxSeamBlend))
    throw ParameterError("seamBlend", "must be in [0, " + std::to_string(kMaxSeamBlend) + "] output pixels, got " +
                                          std::to_string(options.seamBlend));
  if (!(options.collapseTolerance >= 0.0 && options.collapseTolerance <= 1.0))
    throw ParameterError("collapseTolerance",
                         "must be in [0, 1] (1 = no guard), got " + std::to_string(options.collapseTolerance));
}

void validateAnalyses(std::span<const ExemplarAnalysis> analyses, const TextureOptimizationOptions& options) {
  const std::vector<AnalysisOptions> wanted = optimizationAnalysisOptions(options);
  if (analyses.size() != wanted.size())
    throw ParameterError("analyses", "expected " + std::to_string(wanted.size()) +
                                         " analyses (see "
                                         "optimizationAnalysisOptions), got " +
                                         std::to_string(analyses.size()));
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    const ExemplarAnalysis& a = analyses[i];
    if ((options.levels > 0 && a.levelCount() != options.levels) || a.levelCount() != analyses[0].levelCount() ||
        a.neighborhoodSize != wanted[i].neighborhoodSize || a.similarCount < wanted[i].similarCount ||
        a.width != analyses[0].width || a.height != analyses[0].height)
      throw ParameterError("analyses", "analysis " + std::to_string(i) +
                                           " does not match optimizationAnalysisOptions (levels, N, k, exemplar)");
  }
}

int roundUp(int value, int unit) {
  return (value + unit - 1) / unit * unit;
}

// The coarsest level's start. Pixels: every pixel a random exemplar pixel (Han et al. 2.3).
// Patches: square blocks of `block` pixels, each a coherent piece of the exemplar at a random
// place (a real arrangement of exemplar structure to optimize, where random pixels make the
// first matches pick the flattest exemplar regions and the E-step wash the output out).
SourceCoordinates startCoordinates(const TextureOptimizationOptions& options, int width, int height, int spacing,
                                   int exemplarWidth, int exemplarHeight) {
  const bool patches = options.start == OptimizationStart::RandomPatches;
  const int block = std::max(1, options.startPatchSize);
  SourceCoordinates coords(0, 0, width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int bx = patches ? x / block : x, by = patches ? y / block : y;
      const std::uint64_t key = hashKey(options.seed, latticeId(bx, by), 0x0971);
      std::int64_t sx = uniformBelow(key, std::uint32_t(exemplarWidth));
      std::int64_t sy = uniformBelow(mix64(key), std::uint32_t(exemplarHeight));
      if (patches) sx += std::int64_t(x - bx * block) * spacing, sy += std::int64_t(y - by * block) * spacing;
      coords.at(x, y)[0] = wrapIndex(sx, exemplarWidth);
      coords.at(x, y)[1] = wrapIndex(sy, exemplarHeight);
    }
  return coords;
}

// A start given at the finest level, read at the coarsest: its pixel (x, y) is the finest
// pixel `step` (x, y) (clamped to the given size; stack coordinates keep full resolution).
SourceCoordinates sampledCoordinates(const SourceCoordinates& given, int width, int height, int step) {
  SourceCoordinates out(0, 0, width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::int32_t* s =
          given.at(given.x0 + std::min(x * step, given.width - 1), given.y0 + std::min(y * step, given.height - 1));
      out.at(x, y)[0] = s[0], out.at(x, y)[1] = s[1];
    }
  return out;
}

// Bilinear resampling on the torus to width x height: the least-squares output's start at a
// finer level.
Image upsampleColors(const Image& coarse, int width, int height) {
  Image fine(width, height, coarse.channels);
  const double sx = double(coarse.width) / width, sy = double(coarse.height) / height;
  parallelForChunks(0, fine.height, 8, [&](std::int64_t begin, std::int64_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < fine.width; ++x)
        coarse.sampleBilinearWrapped((x + 0.5) * sx, (y + 0.5) * sy, fine.pixel(x, y));
  });
  return fine;
}

// Exemplar pixel indices (the discrete steps' sources) back into source coordinates.

void assignSources(std::span<const std::int32_t> sources, int exemplarWidth, SourceCoordinates& coords) {
  for (std::size_t i = 0; i < sources.size(); ++i) {
    coords.xy[2 * i] = sources[i] % exemplarWidth;
    coords.xy[2 * i + 1] = sources[i] / exemplarWidth;
  }
}

// Most E+M iterations per neighborhood size at `level` of `levels`.
int iterationsAt(const TextureOptimizationOptions& options, int level, int levels) {
  return !isLeastSquares(options) && level + 1 == levels ? options.finestIterations : options.maxIterations;
}

// The state one level carries between neighborhood sizes and iterations.
struct LevelState {
  SourceCoordinates coords;  // discrete
  Image colors;              // least squares
};

// E+M iterations at one level and neighborhood size, until no match changes.
void optimizeScale(std::span<const ExemplarAnalysis> analyses, const TextureOptimizationOptions& options, int level,
                   std::size_t scale, LevelState& state, std::vector<OptimizationIteration>& history,
                   Progress& progress) {
  const ExemplarAnalysis& analysis = analyses[scale];
  const int size = options.neighborhoodSizes[scale];
  if (!isLeastSquares(options)) {
    // Random candidates bring in exemplar parts that no coherent candidate proposes; by the
    // finest level the coarser ones have done that (12 GIMP exemplars at 256^2 and 512^2 without
    // them there: coherence, its 90th percentile and completeness within 1%, 0.81x the time).
    TextureOptimizationOptions scaleOptions = options;
    if (level + 1 == analysis.levelCount()) scaleOptions.randomCandidates = 0;
    scaleOptions.maxIterations = iterationsAt(options, level, analysis.levelCount());
    OptimizationGrid grid(analysis, level, state.coords.width, state.coords.height, size);
    std::vector<std::int32_t> sources = state.coords.pixelIndices(analysis.width);
    detail::optimizeDiscreteScale(grid, analyses, level, scale, scaleOptions, sources, history, progress);
    assignSources(sources, analysis.width, state.coords);
    return;
  }
  const OptimizationGrid grid(analysis, level, state.colors.width, state.colors.height, size);
  // Exact search, a fair baseline; over the allowed match centres only.
  std::vector<std::int32_t> allowed;
  for (std::int32_t pixel = 0; pixel < analysis.width * analysis.height; ++pixel)
    if (grid.window.isAllowedCentre(pixel)) allowed.push_back(pixel);
  const ProjectedNeighborhoodIndex index(analysis.levels[level].projectedVectors(), std::move(allowed));
  Matches matches(grid.activeCount());
  auto match = [&] {
    return detail::matchLeastSquares(grid, analysis.levels[level].pca, index, state.colors, matches);
  };
  auto update = [&] { state.colors = detail::updateLeastSquares(grid, matches, options.robustExponent); };
  auto record = [&](int iteration, std::int64_t changed, double seconds) {
    history.push_back(
        {level, size, iteration, detail::normalizedEnergy(matches, size), changed, grid.activeCount(), seconds});
  };
  detail::iterateExpectationMaximization(options.maxIterations, match, update, match, record, progress);
}

SourceCoordinates cropCoordinates(const SourceCoordinates& coords, int width, int height) {
  SourceCoordinates out(0, 0, width, height);
  for (int y = 0; y < height; ++y) std::copy_n(coords.at(0, y), 2 * std::size_t(width), out.at(0, y));
  return out;
}

// Every level's output size and the level optimization starts at.
struct LevelPlan {
  int first = 0;
  std::vector<int> widths, heights;
};

LevelPlan planLevels(std::span<const ExemplarAnalysis> analyses, const TextureOptimizationOptions& options, int width,
                     int height) {
  const ExemplarAnalysis& base = analyses.back();
  const int levels = base.levelCount();
  // Each level's torus holds whole active-set strides; a level is half the next one's size,
  // rounded up to a stride. The finest is the output itself when its sides are multiples of
  // the largest stride (then it tiles seamlessly).
  int maxStride = 1;
  for (int n : options.neighborhoodSizes) maxStride = std::max(maxStride, detail::activeStride(n));
  LevelPlan plan;
  plan.widths.assign(std::size_t(levels), 0), plan.heights.assign(std::size_t(levels), 0);
  plan.widths.back() = roundUp(width, maxStride), plan.heights.back() = roundUp(height, maxStride);
  for (int level = levels - 2; level >= 0; --level) {
    plan.widths[std::size_t(level)] = roundUp((plan.widths[std::size_t(level) + 1] + 1) / 2, maxStride);
    plan.heights[std::size_t(level)] = roundUp((plan.heights[std::size_t(level) + 1] + 1) / 2, maxStride);
  }
  // The first level whose largest neighborhood fits inside the exemplar without wrapping: at a
  // coarser one a tiled copy of a small (toroidal) exemplar is a zero-energy optimum, and the
  // optimization settles on that lattice (GIMP leaves, 50^2, at 256^2: lattice 0.5).
  const int largest = *std::max_element(options.neighborhoodSizes.begin(), options.neighborhoodSizes.end());
  while (plan.first + 1 < levels && !detail::ExemplarWindow(base, plan.first, largest).bounded) ++plan.first;
  return plan;
}

}  // namespace

SourceCoordinates parallelOptimizationStart(const ExemplarAnalysis& parallelAnalysis,
                                            const ParallelSynthesisOptions& parallel,
                                            std::span<const ExemplarAnalysis> analyses,
                                            const TextureOptimizationOptions& options, int width, int height,
                                            Progress& progress) {
  validate(options);
  validateAnalyses(analyses, options);
  const LevelPlan plan = planLevels(analyses, options, width, height);
  const int spacing = analyses.back().levels[std::size_t(plan.first)].spacing;
  // Without the continuation bias: the optimization rearranges the start's patches anyway, and
  // 12 GIMP exemplars at 256^2 end 1% less coherent from a biased start (90th percentile at or
  // below G'MIC's on 5 instead of 7).
  ParallelSynthesisOptions start = parallel;
  start.continuationBias = 0;
  for (int level = 0; level < parallelAnalysis.levelCount(); ++level)
    if (parallelAnalysis.levels[std::size_t(level)].spacing == spacing)
      return synthesizeParallelLevelCoordinates(parallelAnalysis, start, level, 0, 0,
                                                plan.widths[std::size_t(plan.first)],
                                                plan.heights[std::size_t(plan.first)], progress);
  return synthesizeParallelCoordinates(parallelAnalysis, start, 0, 0, width, height, progress);
}

std::string optimizationSolverName(OptimizationSolver solver) {
  return solver == OptimizationSolver::Discrete ? "discrete" : "least-squares";
}

OptimizationSolver parseOptimizationSolver(const std::string& name) {
  if (name == "discrete") return OptimizationSolver::Discrete;
  if (name == "least-squares") return OptimizationSolver::LeastSquares;
  throw ParameterError("solver", "must be 'discrete' or 'least-squares', got '" + name + "'");
}

std::vector<AnalysisOptions> optimizationAnalysisOptions(const TextureOptimizationOptions& options) {
  validate(options);
  std::vector<AnalysisOptions> all;
  for (std::size_t i = 0; i < options.neighborhoodSizes.size(); ++i) {
    AnalysisOptions analysis;
    analysis.levelCount = options.levels;
    analysis.pcaDimensions = options.pcaDimensions;
    analysis.neighborhoodSize = options.neighborhoodSizes[i];
    // The discrete solver's candidate sets come from the last size's similarity sets; the
    // least-squares M-step searches a KD-tree instead.
    const bool last = i + 1 == options.neighborhoodSizes.size();
    analysis.similarCount = last && !isLeastSquares(options) ? options.similarCount : 1;
    all.push_back(analysis);
  }
  return all;
}

std::vector<AnalysisOptions> withFeatureChannel(std::vector<AnalysisOptions> analyses, const Image& exemplar,
                                                float weight) {
  if (!(weight >= 0) || !std::isfinite(weight))
    throw ParameterError("feature weight", std::to_string(weight) + " is not a finite weight >= 0");
  if (weight == 0) return analyses;
  const Image mask = distinctiveFeatureMask(exemplar, kDistinctivePercent);
  if (mask.empty()) return analyses;
  for (AnalysisOptions& analysis : analyses) {
    analysis.featureMask = mask;
    analysis.featureWeight = weight;
  }
  return analyses;
}

namespace {

std::vector<ExemplarAnalysis> analyzedCached(const Image& exemplar, std::span<const AnalysisOptions> wanted,
                                             const std::string& cacheDirectory, Progress& progress) {
  std::vector<ExemplarAnalysis> analyses;
  for (const AnalysisOptions& analysisOptions : wanted)
    analyses.push_back(analyzeExemplarCached(exemplar, analysisOptions, cacheDirectory, progress));
  return analyses;
}

}  // namespace

std::vector<ExemplarAnalysis> cachedOptimizationAnalyses(const Image& exemplar,
                                                         const TextureOptimizationOptions& options,
                                                         const std::string& cacheDirectory, Progress& progress) {
  return analyzedCached(exemplar, optimizationAnalysisOptions(options), cacheDirectory, progress);
}

FeatureAnalyses cachedFeatureAnalyses(const Image& exemplar, const TextureOptimizationOptions& options,
                                      std::string cacheDirectory, Progress& progress) {
  return [&exemplar, options, cacheDirectory = std::move(cacheDirectory), &progress] {
    const std::vector<AnalysisOptions> featured =
        withFeatureChannel(optimizationAnalysisOptions(options), exemplar, kOptimizationFeatureWeight);
    if (featured.front().featureMask.empty()) return std::vector<ExemplarAnalysis>{};  // no distinctive colors
    return analyzedCached(exemplar, featured, cacheDirectory, progress);
  };
}

TextureOptimizationResult optimizeTexture(std::span<const ExemplarAnalysis> analyses,
                                          const TextureOptimizationOptions& options, int width, int height,
                                          Progress& progress, const SourceCoordinates* startCoords,
                                          const FeatureAnalyses& featureAnalyses) {
  validate(options);
  if (width <= 0) throw ParameterError("width", "must be > 0, got " + std::to_string(width));
  if (height <= 0) throw ParameterError("height", "must be > 0, got " + std::to_string(height));
  validateAnalyses(analyses, options);
  const ExemplarAnalysis& base = analyses.back();
  const int levels = base.levelCount();
  const LevelPlan plan = planLevels(analyses, options, width, height);
  const std::vector<int>&widths = plan.widths, &heights = plan.heights;
  const int first = plan.first;
  const bool startOnFirstGrid = startCoords && startCoords->width == widths[std::size_t(first)] &&
                                startCoords->height == heights[std::size_t(first)];
  if (startCoords && !startOnFirstGrid && (startCoords->width < width || startCoords->height < height))
    throw ParameterError("start", "covers " + std::to_string(startCoords->width) + "x" +
                                      std::to_string(startCoords->height) + " pixels, neither the " +
                                      std::to_string(width) + "x" + std::to_string(height) +
                                      " output nor the first level's grid");

  TextureOptimizationResult result;
  LevelState state;
  // The analyses the E+M steps read: `analyses`, or from the first level colors alone let
  // collapse on, the feature channel's. Sources index the same exemplar pixels in both, and the
  // guard, the upsampling and the output read colors only (`base`).
  std::vector<ExemplarAnalysis> featured;
  std::span<const ExemplarAnalysis> solving = analyses;
  bool askedForFeatures = false;
  for (int level = first; level < levels; ++level) {
    const int w = widths[level], h = heights[level];
    const int steps = int(options.neighborhoodSizes.size()) * (iterationsAt(options, level, levels) + 1);
    progress.begin("optimize level " + std::to_string(level + 1) + "/" + std::to_string(levels) + " (" +
                       std::to_string(w) + "x" + std::to_string(h) + ")",
                   steps);
    const OptimizationGrid start(base, level, w, h, options.neighborhoodSizes[0]);
    const int spacing = start.window.spacing();
    const SourceCoordinates* given = startCoords;
    if (level == first && given && startOnFirstGrid)
      state.coords = sampledCoordinates(*given, w, h, 1);  // given on this level's grid
    else if (level == first && given)
      state.coords = sampledCoordinates(*given, w, h, 1 << (levels - 1 - level));
    else if (level == first)
      state.coords = startCoordinates(options, w, h, spacing, base.width, base.height);
    else if (!isLeastSquares(options))
      state.coords = upsampleCoordinates(state.coords, SourceCoordinates(0, 0, w, h), spacing, base.width, base.height);
    if (level > first && !isLeastSquares(options))
      jitterCoordinates(state.coords, level, spacing, options.jitter, options.seed, base.width, base.height);
    if (isLeastSquares(options))
      state.colors = level == first ? detail::colorsAt(start, state.coords.pixelIndices(base.width))
                                    : upsampleColors(state.colors, w, h);
    if (isLeastSquares(options)) {
      for (std::size_t scale = 0; scale < options.neighborhoodSizes.size(); ++scale)
        optimizeScale(analyses, options, level, scale, state, result.history, progress);
    } else {
      // The collapse guard: a level whose E+M steps leave it flatter than they found it is
      // undone (its start kept). The large neighborhood alone often flattens a coarse level that
      // the small one then restores (GIMP rock, coarsest level: flat share 0.09, 0.39, then 0.16), so
      // the guard judges the level as a whole.
      const detail::FlatPatchShare flatness(base.levels[std::size_t(level)], base.colorChannels);
      const SourceCoordinates before = state.coords;
      const double flatBefore = flatness.of(before.pixelIndices(base.width), w, h);
      auto collapses = [&] {
        for (std::size_t scale = 0; scale < options.neighborhoodSizes.size(); ++scale)
          optimizeScale(solving, options, level, scale, state, result.history, progress);
        return flatness.of(state.coords.pixelIndices(base.width), w, h) > flatBefore + options.collapseTolerance;
      };
      bool collapsed = collapses();
      if (collapsed && !askedForFeatures && featureAnalyses) {
        askedForFeatures = true;
        progress.end();  // the analysis reports its own stages
        featured = featureAnalyses();
        progress.begin("optimize level " + std::to_string(level + 1) + "/" + std::to_string(levels) +
                           " again, with the feature channel",
                       featured.empty() ? 0 : steps);
        if (!featured.empty()) {
          validateAnalyses(featured, options);
          solving = featured;
          state.coords = before;
          collapsed = collapses();
        }
      }
      if (!featured.empty()) ++result.featureLevels;
      if (collapsed) {
        state.coords = before;
        ++result.undoneLevels;
      }
    }
    progress.end();
  }

  Image colors;
  if (isLeastSquares(options)) {
    colors = std::move(state.colors);
  } else {
    result.coords = cropCoordinates(state.coords, width, height);
    // Feathered on the output itself, so that --apply-coords re-applies the same.
    colors = seamBlendedColors(base.levels.back().image, result.coords, base.colorChannels, options.seamBlend);
  }
  result.colors = colors.crop(0, 0, width, height).withChannels(base.colorChannels);
  return result;
}

}  // namespace texsynth
