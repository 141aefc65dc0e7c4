#include "texsynth/exemplar/analysis.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/exemplar/feature_distance.h"
#include "texsynth/exemplar/gaussian_stack.h"

namespace texsynth {
namespace {

int effectiveExclusionRadius(const AnalysisOptions& options) {
  return options.exclusionRadius < 0 ? options.neighborhoodSize / 2 : options.exclusionRadius;
}

std::string levelLabel(int level, int levelCount) {
  return " (level " + std::to_string(level + 1) + "/" + std::to_string(levelCount) + ")";
}

void requireNeighborhoodSize(const char* name, int n) {
  if (n < 1 || n % 2 == 0 || n > kMaxNeighborhoodSize)
    throw ParameterError(
        name, "must be odd and in 1.." + std::to_string(kMaxNeighborhoodSize) + ", got " + std::to_string(n));
}

}  // namespace

int neighborhoodSizeAt(const AnalysisOptions& options, int level) {
  const std::vector<int>& sizes = options.levelNeighborhoodSizes;
  if (sizes.empty()) return options.neighborhoodSize;
  return sizes[std::size_t(std::min<int>(level, int(sizes.size()) - 1))];
}

void validateAnalysisOptions(const Image& exemplar, const AnalysisOptions& options) {
  if (exemplar.empty()) throw ParameterError("exemplar", "image is empty");
  for (float v : exemplar.pixels)
    if (!std::isfinite(v)) throw ParameterError("exemplar", "contains NaN or infinite values");
  requireNeighborhoodSize("neighborhoodSize", options.neighborhoodSize);
  for (int n : options.levelNeighborhoodSizes) requireNeighborhoodSize("levelNeighborhoodSizes", n);
  if (options.pcaDimensions < 1)
    throw ParameterError("pcaDimensions", "must be at least 1, got " + std::to_string(options.pcaDimensions));
  if (options.similarCount < 1)
    throw ParameterError("similarCount", "must be at least 1, got " + std::to_string(options.similarCount));
  if (options.exclusionRadius < -1)
    throw ParameterError("exclusionRadius", "must be -1 (N/2) or >= 0, got " + std::to_string(options.exclusionRadius));
  const int maxLevels = defaultStackLevelCount(exemplar.width, exemplar.height);
  if (options.levelCount < 0 || options.levelCount > maxLevels)
    throw ParameterError("levelCount", "must be 0 (automatic) or 1.." + std::to_string(maxLevels) + ", got " +
                                           std::to_string(options.levelCount));
  if (!std::isfinite(options.featureWeight) || options.featureWeight < 0.0f)
    throw ParameterError("featureWeight", "must be a finite value >= 0, got " + std::to_string(options.featureWeight));
  const Image& mask = options.featureMask;
  if (!mask.empty() && (mask.width != exemplar.width || mask.height != exemplar.height))
    throw ParameterError("featureMask", "size " + std::to_string(mask.width) + "x" + std::to_string(mask.height) +
                                            " differs from the exemplar's " + std::to_string(exemplar.width) + "x" +
                                            std::to_string(exemplar.height));
}

ExemplarAnalysis analyzeExemplar(const Image& exemplar, const AnalysisOptions& options, Progress& progress) {
  validateAnalysisOptions(exemplar, options);
  ExemplarAnalysis analysis;
  analysis.width = exemplar.width;
  analysis.height = exemplar.height;
  analysis.colorChannels = exemplar.channels;
  analysis.hasFeatureChannel = !options.featureMask.empty();
  analysis.neighborhoodSize = options.neighborhoodSize;
  analysis.similarCount = options.similarCount;
  analysis.exclusionRadius = effectiveExclusionRadius(options);

  SimilarityOptions search = options.search;
  search.count = options.similarCount;
  search.exclusionRadius = analysis.exclusionRadius;

  Image input = exemplar;
  if (analysis.hasFeatureChannel) {
    progress.begin("exemplar: feature distance", 1);
    input = appendChannel(exemplar, featureChannelFromMask(options.featureMask, options.featureWeight));
    progress.advance();
    progress.end();
  }

  progress.begin("exemplar: Gaussian stack", 1);
  GaussianStack stack = buildGaussianStack(input, {options.levelCount});
  progress.advance();
  progress.end();

  const int levelCount = stack.levelCount();
  analysis.levels.resize(levelCount);
  for (int level = 0; level < levelCount; ++level) {
    ExemplarLevel& out = analysis.levels[level];
    out.spacing = stack.spacing(level);
    out.image = std::move(stack.levels[level]);
    out.neighborhoodSize = neighborhoodSizeAt(options, level);
    const NeighborhoodShape shape = out.shape();

    progress.begin("exemplar: PCA" + levelLabel(level, levelCount), 2);
    out.pca = fitNeighborhoodPca(out.image, shape, options.pcaDimensions);
    progress.advance();
    out.projected = projectAllNeighborhoods(out.image, shape, out.pca);
    progress.advance();
    progress.end();

    progress.begin("exemplar: similarity sets" + levelLabel(level, levelCount), std::int64_t(exemplar.pixelCount()));
    out.similar = computeSimilaritySets(out.projectedVectors(), search, progress);
    progress.end();
  }
  return analysis;
}

}  // namespace texsynth
