#include "texsynth/image/histogram_gaussianization.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

double normalCdf(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

void validate(const Image& exemplar, const GaussianizationOptions& options) {
  if (exemplar.empty()) throw ParameterError("exemplar", "image is empty");
  if (options.lutSize < 2) throw ParameterError("lutSize", "must be >= 2, got " + std::to_string(options.lutSize));
  if (!(options.gaussianRange > 0.0f) || !std::isfinite(options.gaussianRange))
    throw ParameterError("gaussianRange", "must be a finite number > 0");
}

// Exemplar value at quantile u of the sorted values (linear between ranks).
float quantile(const std::vector<float>& sorted, double u) {
  double position = std::clamp(u * double(sorted.size()) - 0.5, 0.0, double(sorted.size() - 1));
  std::size_t i = std::min(std::size_t(position), sorted.size() - 1);
  std::size_t j = std::min(i + 1, sorted.size() - 1);
  double f = position - double(i);
  return float(sorted[i] + (sorted[j] - sorted[i]) * f);
}

}  // namespace

double inverseNormalCdf(double u) {
  if (!(u > 0.0 && u < 1.0)) throw ParameterError("u", "inverse normal CDF needs 0 < u < 1");
  // Bisection to bracket, then Newton: robust and plenty fast for the few thousand calls a
  // Gaussianization makes.
  double lo = -40.0, hi = 40.0;
  for (int k = 0; k < 20; ++k) {
    double mid = 0.5 * (lo + hi);
    (normalCdf(mid) < u ? lo : hi) = mid;
  }
  double x = 0.5 * (lo + hi);
  const double invSqrt2Pi = 0.3989422804014327;
  for (int k = 0; k < 8; ++k) {
    double density = invSqrt2Pi * std::exp(-0.5 * x * x);
    if (density < 1e-300) break;
    double step = (normalCdf(x) - u) / density;
    x -= step;
    if (std::abs(step) < 1e-14) break;
  }
  return x;
}

InverseLut::InverseLut(int channels, int size, float range, std::vector<float> entries)
    : channels_(channels),
      size_(size),
      range_(range),
      scale_(float(size - 1) / (2.0f * range)),
      entries_(std::move(entries)) {
  TS_CHECK(size >= 2 && range > 0 && entries_.size() == std::size_t(channels) * size);
}

Image GaussianizedExemplar::toColor(const Image& gaussianImage) const {
  TS_CHECK(gaussianImage.channels == lut.channels());
  Image out(gaussianImage.width, gaussianImage.height, gaussianImage.channels);
  for (std::size_t p = 0; p < gaussianImage.pixelCount(); ++p)
    lut.lookup(&gaussianImage.pixels[p * out.channels], &out.pixels[p * out.channels]);
  return out;
}

GaussianizedExemplar gaussianize(const Image& exemplar, const GaussianizationOptions& options) {
  validate(exemplar, options);
  const std::size_t n = exemplar.pixelCount();
  const int channels = exemplar.channels;

  // Gaussian value of each rank, shared by all channels.
  std::vector<float> gaussianOfRank(n);
  for (std::size_t r = 0; r < n; ++r) gaussianOfRank[r] = float(inverseNormalCdf((double(r) + 0.5) / double(n)));

  GaussianizedExemplar result;
  result.gaussian = Image(exemplar.width, exemplar.height, channels);
  std::vector<float> entries(std::size_t(channels) * options.lutSize);
  std::vector<std::size_t> order(n);
  std::vector<float> sorted(n);
  for (int c = 0; c < channels; ++c) {
    auto value = [&](std::size_t p) { return exemplar.pixels[p * channels + c]; };
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return value(a) < value(b); });
    for (std::size_t r = 0; r < n; ++r) {
      result.gaussian.pixels[order[r] * channels + c] = gaussianOfRank[r];
      sorted[r] = value(order[r]);
    }
    for (int i = 0; i < options.lutSize; ++i) {
      double g = -options.gaussianRange + 2.0 * options.gaussianRange * i / (options.lutSize - 1);
      entries[std::size_t(c) * options.lutSize + i] = quantile(sorted, normalCdf(g));
    }
  }
  result.lut = InverseLut(channels, options.lutSize, options.gaussianRange, std::move(entries));
  return result;
}

}  // namespace texsynth
