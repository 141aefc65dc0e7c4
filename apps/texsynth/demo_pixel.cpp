// The demo's 2D section: parallel and optimize at 256^2, timed and scored.
#include "demo_pixel.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>

#include "cli_common.h"
#include "texsynth/core/timing.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/image/parallel_synthesis.h"
#include "texsynth/image/texture_optimization.h"
#include "texsynth/io/image_io.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

constexpr int kSide = 256;
constexpr int kSeamCrop = 80, kSeamMagnify = 3;  // the seam close-up: a corner, magnified

// `image` magnified `factor` times, each pixel a square.
Image magnified(const Image& image, int factor) {
  Image out(image.width * factor, image.height * factor, image.channels);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      std::copy_n(image.pixel(x / factor, y / factor), image.channels, out.pixel(x, y));
  return out;
}

}  // namespace

std::string fixed3(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

json demoPixelSynthesis(const Image& exemplar, const ExemplarAnalysis& analysis, std::uint64_t seed,
                        const std::string& cacheDirectory, const std::function<std::string(const std::string&)>& out) {
  MetricOptions metricOptions;
  metricOptions.seed = seed;
  json section;

  auto start = std::chrono::steady_clock::now();
  ParallelSynthesisOptions parallelOptions;
  parallelOptions.seed = seed;
  const SourceCoordinates coords = synthesizeParallelCoordinates(analysis, parallelOptions, 0, 0, kSide, kSide);
  const Image parallel = lookupColors(exemplar, coords);
  const double parallelSeconds = secondsSince(start);
  section["parallel"] = metricsJson(evaluateImage(exemplar, parallel, metricOptions));
  section["parallel"]["seconds"] = parallelSeconds;

  TextureOptimizationOptions options;
  options.seed = seed;
  start = std::chrono::steady_clock::now();
  const std::vector<ExemplarAnalysis> analyses = cachedOptimizationAnalyses(exemplar, options, cacheDirectory);
  section["optimize_analysis_seconds"] = secondsSince(start);
  start = std::chrono::steady_clock::now();
  // The start `texsynth image --method optimize` makes (parallel up to the first level it optimizes).
  const SourceCoordinates optimizeStart =
      parallelOptimizationStart(analysis, parallelOptions, analyses, options, kSide, kSide);
  const TextureOptimizationResult result =
      optimizeTexture(analyses, options, kSide, kSide, noProgress(), &optimizeStart,
                      cachedFeatureAnalyses(exemplar, options, cacheDirectory));
  const double optimizeSeconds = secondsSince(start);
  const Image& optimized = result.colors;
  section["optimize"] = metricsJson(evaluateImage(exemplar, optimized, metricOptions));
  section["optimize"]["seconds"] = optimizeSeconds;
  section["optimize"]["undone_levels"] = result.undoneLevels;
  section["optimize"]["feature_levels"] = result.featureLevels;
  // The same coordinates with crisp cuts (--seam-blend 0).
  const Image crisp = lookupColors(exemplar, result.coords);
  section["optimize_crisp"] = metricsJson(evaluateImage(exemplar, crisp, metricOptions));
  section["size"] = kSide;

  writeImage(out("pixel_synthesis.png"), sideBySide({exemplar, parallel, optimized}, 8));
  writeImage(out("pixel_seams.png"), sideBySide({magnified(crisp.crop(0, 0, kSeamCrop, kSeamCrop), kSeamMagnify),
                                                 magnified(optimized.crop(0, 0, kSeamCrop, kSeamCrop), kSeamMagnify)},
                                                8));
  return section;
}

std::string pixelMarkdown(const json& pixel, const json& tiling) {
  std::ostringstream md;
  md << "## 2D synthesis\n\n![exemplar, parallel, optimize](pixel_synthesis.png)\n\n";
  md << "The exemplar, then " << pixel["size"] << "x" << pixel["size"]
     << " outputs: `texsynth image --method parallel` (Lefebvre & Hoppe 2005, from random coordinates at the "
        "coarsest level that fits the exemplar) and `--method optimize` (texture optimization with the discrete "
        "solver, started from parallel synthesis run up to its first level, as the CLI does, with the "
        "exemplar-usage term and weighted votes). Scored by "
        "`texsynth eval` against a 2x2 tiling of the exemplar:\n\n";
  md << "| output | time | coherence | coherence p90 | completeness | histogram | sharpness | lattice |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  auto row = [&](const char* name, const json& m, const std::string& time) {
    md << "| " << name << " | " << time << " | " << fixed3(m["coherence"]) << " | " << fixed3(m["coherence_p90"])
       << " | " << fixed3(m["completeness"]) << " | " << fixed3(m["histogram"]) << " | " << fixed3(m["sharpness"])
       << " | " << fixed3(m["lattice"]) << " |\n";
  };
  row("tiling 2x2", tiling, "");
  row("parallel", pixel["parallel"], fixed3(pixel["parallel"]["seconds"]) + " s");
  row("optimize", pixel["optimize"], fixed3(pixel["optimize"]["seconds"]) + " s");
  row("optimize, crisp cuts", pixel["optimize_crisp"], "");
  md << "\nLower is better except sharpness (1 = as crisp as the exemplar). A tiling copies the exemplar, so its "
        "coherence is near 0, but its lattice (a shifted repeat of the same content) is near 1. Coherence p90 is the "
        "worst tenth of the output's patches, where seams show. The optimizer's "
        "exemplar analyses took "
     << fixed3(pixel["optimize_analysis_seconds"])
     << " s (cached for the next run). Levels undone by the collapse "
        "guard (their E+M steps left them flatter than their start): "
     << pixel["optimize"]["undone_levels"] << "; levels run with the feature channel, which the guard falls back to "
     << "on a flat-background exemplar whose thin features colors alone lose (GIMP cracked): "
     << pixel["optimize"]["feature_levels"] << ".\n\n";
  md << "![crisp cuts, feathered seams](pixel_seams.png)\n\nA corner of the optimize output magnified " << kSeamMagnify
     << "x: left with crisp cuts where two exemplar pieces meet (`--seam-blend 0`, the row above), right as "
        "written, the seams feathered over 1.5 pixels (`--seam-blend`); pixels inside a piece keep their exact "
        "colour.\n\n";
  return md.str();
}

}  // namespace texsynth::cli
