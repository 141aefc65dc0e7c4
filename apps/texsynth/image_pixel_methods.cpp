// The pixel-based methods of `texsynth image`: they synthesize source coordinates into the
// exemplar (written with --coords, re-applied to other maps with --apply-coords).
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "image_args.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/exemplar/gaussian_stack.h"
#include "texsynth/image/parallel_synthesis.h"
#include "texsynth/image/seam_blend.h"
#include "texsynth/image/texture_optimization.h"
#include "texsynth/io/image_io.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

// Source coordinates as a two-channel float image (x, y into the exemplar), for --coords.
Image coordinateImage(const SourceCoordinates& coords) {
  Image image(coords.width, coords.height, 2);
  for (std::size_t i = 0; i < coords.xy.size(); ++i) image.pixels[i] = float(coords.xy[i]);
  return image;
}

// "17,9": odd neighborhood sizes.
std::vector<int> parseNeighborhoods(const std::string& text) {
  std::vector<int> sizes;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    int value = 0;
    try {
      value = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || value < 3 || value % 2 == 0 || value > kMaxNeighborhoodSize)
      throw ParameterError("--neighborhood", "expected odd sizes in 3.." + std::to_string(kMaxNeighborhoodSize) +
                                                 " separated by commas (e.g. 17,9), got '" + text + "'");
    sizes.push_back(value);
  }
  if (sizes.empty()) throw ParameterError("--neighborhood", "expected at least one size, got '" + text + "'");
  return sizes;
}

}  // namespace

Image synthesizeParallelWindow(const Image& exemplar, const ImageArgs& args, const Window& window,
                               const GlobalOptions& globals, json& report) {
  auto progress = makeProgress(globals);
  AnalysisOptions analysisOptions;
  if (args.levels >= 0) analysisOptions.levelCount = args.levels;
  if (args.similarCount >= 0) analysisOptions.similarCount = args.similarCount;
  if (!args.neighborhoods.empty()) analysisOptions.levelNeighborhoodSizes = parseNeighborhoods(args.neighborhoods);
  ExemplarAnalysis analysis = analyzeExemplarCached(exemplar, analysisOptions, defaultCacheDirectory(), *progress);
  ParallelSynthesisOptions options;
  options.seed = globals.seed;
  options.passes = args.passes;
  options.subpassGrid = args.subpasses;
  if (args.footprint >= 0) options.coarsestFootprint = args.footprint;
  if (!args.jitter.empty()) {
    auto [coarse, rest] = parseFloatPair(args.jitter, "--jitter");
    options.jitter.assign(analysis.levelCount(), rest);
    options.jitter[0] = coarse;
  }
  SourceCoordinates coords = synthesizeParallelCoordinates(analysis, options, int(window.x), int(window.y),
                                                           window.width, window.height, *progress);
  if (!args.coords.empty()) writeImage(args.coords, coordinateImage(coords));
  report["levels"] = analysis.levelCount();
  return lookupColors(exemplar, coords);
}

Image synthesizeOptimized(const Image& exemplar, const ImageArgs& args, int width, int height,
                          const GlobalOptions& globals, json& report) {
  TextureOptimizationOptions options;
  options.seed = globals.seed;
  options.solver = parseOptimizationSolver(args.solver);
  if (args.levels >= 0)
    options.levels = args.levels;
  else  // the default 3, or as many as a tiny exemplar has
    options.levels = std::min(options.levels, defaultStackLevelCount(exemplar.width, exemplar.height));
  if (!args.neighborhoods.empty()) options.neighborhoodSizes = parseNeighborhoods(args.neighborhoods);
  if (args.iterations > 0) options.maxIterations = options.finestIterations = args.iterations;
  if (!args.jitter.empty()) options.jitter = parseFloatPair(args.jitter, "--jitter").second;
  if (args.similarCount >= 0) options.similarCount = args.similarCount;
  if (args.coverage >= 0) options.coverageWeight = args.coverage;
  if (args.voteExponent >= 0) options.voteExponent = args.voteExponent;
  if (args.seamBlend >= 0) options.seamBlend = args.seamBlend;
  if (options.solver == OptimizationSolver::LeastSquares && args.seamBlend >= 0)
    throw ParameterError("--seam-blend", "the least-squares solver blends colors everywhere; use --solver discrete");
  if (options.solver == OptimizationSolver::LeastSquares && !args.coords.empty())
    throw ParameterError("--coords",
                         "the least-squares solver blends colors, so it has no source coordinates; use "
                         "--solver discrete");
  auto progress = makeProgress(globals);
  const std::vector<ExemplarAnalysis> analyses =
      cachedOptimizationAnalyses(exemplar, options, defaultCacheDirectory(), *progress);
  // --start parallel: the parallel method at its defaults, less its continuation bias
  // (parallelOptimizationStart), run up to the first level optimized.
  std::optional<SourceCoordinates> start;
  if (args.start == "parallel" && options.solver == OptimizationSolver::Discrete) {
    ParallelSynthesisOptions parallel;
    parallel.seed = globals.seed;
    const ExemplarAnalysis analysis = analyzeExemplarCached(exemplar, {}, defaultCacheDirectory(), *progress);
    start = parallelOptimizationStart(analysis, parallel, analyses, options, width, height, *progress);
  }
  if (args.start == "pixels") options.start = OptimizationStart::RandomPixels;
  TextureOptimizationResult result =
      optimizeTexture(analyses, options, width, height, *progress, start ? &*start : nullptr,
                      cachedFeatureAnalyses(exemplar, options, defaultCacheDirectory(), *progress));
  if (!args.coords.empty()) writeImage(args.coords, coordinateImage(result.coords));

  json iterations = json::array();
  for (const OptimizationIteration& step : result.history)
    iterations.push_back({{"level", step.level},
                          {"neighborhood", step.neighborhoodSize},
                          {"iteration", step.iteration},
                          {"energy", step.energy},
                          {"changed_matches", step.changedMatches},
                          {"neighborhoods", step.neighborhoods},
                          {"seconds", step.seconds}});
  report["solver"] = args.solver;
  report["levels"] = options.levels;
  report["iterations"] = iterations;
  report["undone_levels"] = result.undoneLevels;
  report["feature_levels"] = result.featureLevels;
  if (!result.history.empty()) report["final_energy"] = result.history.back().energy;
  return result.colors;
}

Image applyCoordinates(const Image& map, const ImageArgs& args, json& report) {
  if (readImageInfo(args.applyCoords).format != "exr")  // only float EXR holds coordinates exactly
    throw InputError(args.applyCoords, "is not an OpenEXR file; source coordinates come only from --coords as .exr");
  const Image coords = readImage(args.applyCoords);
  if (coords.channels < 2)
    throw InputError(args.applyCoords, "holds " + std::to_string(coords.channels) +
                                           " channel(s); source coordinates need two (x, y), as --coords writes");
  SourceCoordinates source(0, 0, coords.width, coords.height);
  for (int y = 0; y < coords.height; ++y)
    for (int x = 0; x < coords.width; ++x) {
      const float* c = coords.pixel(x, y);
      for (int axis = 0; axis < 2; ++axis) {
        const int limit = axis == 0 ? map.width : map.height;
        if (!std::isfinite(c[axis]) || c[axis] < 0 || c[axis] >= float(limit) || c[axis] != std::floor(c[axis]))
          throw InputError(args.applyCoords, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") holds " +
                                                 (axis == 0 ? "x" : "y") + " = " + std::to_string(c[axis]) +
                                                 ", not a pixel of the " + std::to_string(map.width) + "x" +
                                                 std::to_string(map.height) + " map '" + args.exemplar +
                                                 "' (coordinates must come from an exemplar of the same size)");
        source.at(x, y)[axis] = std::int32_t(c[axis]);
      }
    }
  report["coords"] = args.applyCoords;
  // Feathered as optimize feathers its output (the same default), so its coordinates re-apply
  // to the same picture.
  const float seamBlend = args.seamBlend >= 0 ? args.seamBlend : TextureOptimizationOptions{}.seamBlend;
  return seamBlendedColors(map, source, 0, seamBlend);
}

}  // namespace texsynth::cli
