// Parallel synthesis driver: plans, from the requested window down to the coarsest level,
// the padded region each level must synthesize, then runs upsampling, jitter and correction
// from the coarsest level up, and finally looks colors up at the finest coordinates.
#include "texsynth/image/parallel_synthesis.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "texsynth/core/parallel.h"
#include "texsynth/image/window_support.h"

namespace texsynth {
namespace {

int floorDiv2(int v) {
  return v >= 0 ? v / 2 : -((1 - v) / 2);
}

struct Region {
  int x0, y0, width, height;
  Region grown(int margin) const { return {x0 - margin, y0 - margin, width + 2 * margin, height + 2 * margin}; }
  // The coarser-level pixels that the upsampling of this region reads.
  Region parents() const {
    const int px0 = floorDiv2(x0), py0 = floorDiv2(y0);
    return {px0, py0, floorDiv2(x0 + width - 1) - px0 + 1, floorDiv2(y0 + height - 1) - py0 + 1};
  }
  SourceCoordinates coordinates() const { return {x0, y0, width, height}; }
};

void validate(const ExemplarAnalysis& analysis, const ParallelSynthesisOptions& options, int x0, int y0, int w, int h) {
  if (analysis.levels.empty() || analysis.width <= 0 || analysis.height <= 0)
    throw ParameterError("analysis", "is empty (run analyzeExemplar first)");
  requireWindow(x0, y0, w, h);
  if (options.passes < 0) throw ParameterError("passes", "must be >= 0, got " + std::to_string(options.passes));
  if (options.subpassGrid < 1 || options.subpassGrid > 4)
    throw ParameterError(
        "subpasses", "the subpass grid s (s^2 subpasses) must be in 1..4, got " + std::to_string(options.subpassGrid));
  if (!options.jitter.empty() && int(options.jitter.size()) != analysis.levelCount())
    throw ParameterError("jitter", "needs one value per level (" + std::to_string(analysis.levelCount()) + "), got " +
                                       std::to_string(options.jitter.size()));
  requireFiniteAtLeast("jitter", options.defaultJitter, 0.0f);
  for (float r : options.jitter) requireFiniteAtLeast("jitter", r, 0.0f);
  requireFiniteAtLeast("coarsestFootprint", options.coarsestFootprint, 0.0f);
  if (!(options.continuationBias >= 0.0f && options.continuationBias < 1.0f))
    throw ParameterError("continuationBias", "must be in [0, 1), got " + std::to_string(options.continuationBias));
  if (options.startPasses < 0)
    throw ParameterError("startPasses", "must be >= 0, got " + std::to_string(options.startPasses));
}

}  // namespace

int firstSynthesizedLevel(const ExemplarAnalysis& analysis, float coarsestFootprint) {
  if (coarsestFootprint <= 0) return 0;
  const double side = std::min(analysis.width, analysis.height);
  for (int l = 0; l < analysis.levelCount(); ++l)
    if (analysis.levels[l].neighborhoodSize * analysis.levels[l].spacing <= coarsestFootprint * side) return l;
  return analysis.levelCount() - 1;
}

SourceCoordinates synthesizeParallelLevelCoordinates(const ExemplarAnalysis& analysis,
                                                     const ParallelSynthesisOptions& options, int level, int x0, int y0,
                                                     int w, int h, Progress& progress) {
  validate(analysis, options, x0, y0, w, h);
  const int levels = analysis.levelCount();
  if (level < 0 || level >= levels)
    throw ParameterError("level", "must be in 0.." + std::to_string(levels - 1) + ", got " + std::to_string(level));
  const int first = firstSynthesizedLevel(analysis, options.coarsestFootprint);
  if (level < first) {
    // Synthesis starts finer than asked: the finer grid read every 2^(first - level) pixels.
    const int step = 1 << (first - level);
    const SourceCoordinates fine = synthesizeParallelLevelCoordinates(analysis, options, first, x0 * step, y0 * step,
                                                                      (w - 1) * step + 1, (h - 1) * step + 1, progress);
    SourceCoordinates coarse(x0, y0, w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::int32_t* source = fine.at(fine.x0 + x * step, fine.y0 + y * step);
        std::int32_t* target = coarse.at(x0 + x, y0 + y);
        target[0] = source[0], target[1] = source[1];
      }
    return coarse;
  }
  // From random coordinates, the first level needs more passes to grow coherent patches.
  auto passes = [&](int l) {
    return l == first && options.coarsestFootprint > 0 && options.passes > 0
               ? std::max(options.startPasses, options.passes)
               : options.passes;
  };
  auto margin = [&](int l) { return correctionMargin(analysis, l, passes(l), options.subpassGrid); };

  // corrected[l]: the region level l must deliver; the asked level delivers the window itself.
  std::vector<Region> corrected(static_cast<std::size_t>(level + 1));
  corrected[level] = {x0, y0, w, h};
  for (int l = level; l > first; --l) corrected[l - 1] = corrected[l].grown(margin(l)).parents();

  progress.begin("parallel synthesis", level + 1 - first);
  SourceCoordinates coords;
  for (int l = first; l <= level; ++l) {
    const int spacing = analysis.levels[l].spacing;
    const Region start = corrected[l].grown(margin(l));
    if (l > first)
      coords = upsampleCoordinates(coords, start.coordinates(), spacing, analysis.width, analysis.height);
    else if (options.coarsestFootprint > 0)
      coords = randomCoordinates(start.x0, start.y0, start.width, start.height, options.seed, l, analysis.width,
                                 analysis.height);
    else
      coords =
          tilingCoordinates(start.x0, start.y0, start.width, start.height, spacing, analysis.width, analysis.height);
    const float strength = options.jitter.empty() ? options.defaultJitter : options.jitter[l];
    jitterCoordinates(coords, l, spacing, strength, options.seed, analysis.width, analysis.height);
    for (int pass = 0; pass < passes(l); ++pass)
      coords = correctCoordinates(analysis, l, coords, options.subpassGrid, options.continuationBias);
    TS_CHECK(coords.x0 == corrected[l].x0 && coords.width == corrected[l].width);
    TS_CHECK(coords.y0 == corrected[l].y0 && coords.height == corrected[l].height);
    progress.advance(1);
  }
  progress.end();
  return coords;
}

SourceCoordinates synthesizeParallelCoordinates(const ExemplarAnalysis& analysis,
                                                const ParallelSynthesisOptions& options, int x0, int y0, int w, int h,
                                                Progress& progress) {
  // synthesizeParallelLevelCoordinates validates (an empty analysis before its level count is read).
  return synthesizeParallelLevelCoordinates(analysis, options, analysis.levelCount() - 1, x0, y0, w, h, progress);
}

Image lookupColors(const Image& image, const SourceCoordinates& coords, int channels) {
  if (image.empty()) throw ParameterError("image", "is empty");
  if (channels < 0 || channels > image.channels)
    throw ParameterError("channels",
                         "must be in [0, " + std::to_string(image.channels) + "], got " + std::to_string(channels));
  if (channels == 0) channels = image.channels;
  Image out(coords.width, coords.height, channels);
  parallelForChunks(0, coords.height, kRowChunk, [&](std::int64_t begin, std::int64_t end) {
    for (int j = int(begin); j < int(end); ++j)
      for (int i = 0; i < coords.width; ++i) {
        const std::int32_t* source = coords.at(coords.x0 + i, coords.y0 + j);
        // Coordinates from another exemplar of a different size still wrap onto this map.
        const float* color = image.pixel(int(source[0] % image.width), int(source[1] % image.height));
        std::copy(color, color + channels, out.pixel(i, j));
      }
  });
  return out;
}

Image synthesizeParallel(const ExemplarAnalysis& analysis, const ParallelSynthesisOptions& options, int x0, int y0,
                         int w, int h, Progress& progress) {
  SourceCoordinates coords = synthesizeParallelCoordinates(analysis, options, x0, y0, w, h, progress);
  return lookupColors(analysis.levels.back().image, coords, analysis.colorChannels);
}

}  // namespace texsynth
