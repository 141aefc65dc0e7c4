#include "texsynth/eval/metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "metrics_detail.h"
#include "texsynth/core/error.h"
#include "texsynth/eval/histogram_distance.h"
#include "texsynth/eval/lattice.h"
#include "texsynth/eval/periodicity.h"
#include "texsynth/eval/sharpness.h"

namespace texsynth {
namespace eval_detail {
namespace {

// Square root of the mean of the matches' mean squared differences, summed in index order.
double rootMeanSquare(const std::vector<PatchMatch>& matches) {
  double sum = 0;
  for (const PatchMatch& match : matches) sum += match.meanSquared;
  return std::sqrt(sum / double(matches.size()));
}

// The 90th percentile (nearest rank) of the matches' root mean squared differences.
double tail(const std::vector<PatchMatch>& matches) {
  if (matches.empty()) return 0;
  std::vector<double> values(matches.size());
  for (std::size_t i = 0; i < matches.size(); ++i) values[i] = matches[i].meanSquared;
  const auto rank = std::ptrdiff_t(std::ceil(0.9 * double(values.size()))) - 1;
  std::nth_element(values.begin(), values.begin() + rank, values.end());
  return std::sqrt(values[std::size_t(rank)]);
}

}  // namespace

void validateOptions(const MetricOptions& options) {
  if (options.patchSize < 1 || options.patchSize % 2 == 0)
    throw ParameterError("patchSize", "must be a positive odd number, got " + std::to_string(options.patchSize));
  if (options.periodicitySamples < 1)
    throw ParameterError("periodicitySamples", "must be at least 1, got " + std::to_string(options.periodicitySamples));
  if (!(options.duplicateThreshold >= 0) || !std::isfinite(options.duplicateThreshold))
    throw ParameterError("duplicateThreshold",
                         "must be a finite value >= 0, got " + std::to_string(options.duplicateThreshold));
  if (options.slicesPerAxis < 1)
    throw ParameterError("slicesPerAxis", "must be at least 1, got " + std::to_string(options.slicesPerAxis));
}

Image toRgb255(const Image& image, const std::string& what, int patchSize) {
  if (image.empty()) throw ParameterError(what, "is empty");
  if (image.width < patchSize || image.height < patchSize)
    throw ParameterError(what, "is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                   ", smaller than the " + std::to_string(patchSize) + "x" + std::to_string(patchSize) +
                                   " patch");
  Image rgb = image.withChannels(3);
  for (float& value : rgb.pixels) {
    if (!std::isfinite(value)) throw ParameterError(what, "contains non-finite values (NaN or infinity)");
    value *= 255.0f;
  }
  return rgb;
}

QualityMetrics evaluateRgb255(const PatchIndex& exemplarIndex, const Image& output, const MetricOptions& options) {
  PatchIndex outputIndex(output, options.patchSize);
  QualityMetrics metrics;
  const std::vector<PatchMatch> matches = exemplarIndex.nearest(output);
  metrics.coherence = rootMeanSquare(matches);
  metrics.coherenceTail = tail(matches);
  metrics.completeness = rootMeanSquare(outputIndex.nearest(exemplarIndex.image()));
  metrics.histogram = histogramDistance(exemplarIndex.image(), output);
  const double exemplarGradient = meanGradientMagnitude(exemplarIndex.image());
  metrics.sharpness = exemplarGradient > 0 ? meanGradientMagnitude(output) / exemplarGradient : 0.0;
  metrics.periodicity =
      periodicity(outputIndex, {options.periodicitySamples, options.duplicateThreshold, options.seed});
  metrics.lattice = latticeStrength(output);
  return metrics;
}

}  // namespace eval_detail

QualityMetrics evaluateImage(const Image& exemplar, const Image& output, const MetricOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  eval_detail::validateOptions(options);
  Image exemplarRgb = eval_detail::toRgb255(exemplar, "exemplar", options.patchSize);
  Image outputRgb = eval_detail::toRgb255(output, "output", options.patchSize);
  QualityMetrics metrics = eval_detail::evaluateRgb255(PatchIndex(exemplarRgb, options.patchSize), outputRgb, options);
  metrics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return metrics;
}

}  // namespace texsynth
