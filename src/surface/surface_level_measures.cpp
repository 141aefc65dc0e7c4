// Flatness and histogram distance of one level's coordinates (surface_level_measures.h).
#include "texsynth/surface/surface_level_measures.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"
#include "texsynth/surface/surface_parallel.h"

namespace texsynth {
namespace {

// Standard deviation of a set of colors: the RMS distance of its values from their channel means.
class Spread {
 public:
  explicit Spread(int channels) : sum_(std::size_t(channels), 0.0), squares_(std::size_t(channels), 0.0) {}
  void add(const float* color) {
    for (std::size_t c = 0; c < sum_.size(); ++c) sum_[c] += color[c], squares_[c] += double(color[c]) * color[c];
    ++count_;
  }
  double deviation() const {
    if (count_ == 0) return 0;
    double variance = 0;
    for (std::size_t c = 0; c < sum_.size(); ++c) {
      const double mean = sum_[c] / count_;
      variance += std::max(0.0, squares_[c] / count_ - mean * mean);
    }
    return std::sqrt(variance / double(sum_.size()));
  }

 private:
  std::vector<double> sum_, squares_;
  int count_ = 0;
};

}  // namespace

SurfaceLevelMeasures measureSurfaceLevel(const SurfaceStencil& stencil, const ExemplarLevel& level,
                                         std::span<const Vec2f> coordinates) {
  const Image& image = level.image;
  const int channels = image.channels, h = level.spacing, radius = stencil.size / 2;
  std::vector<float> colors(coordinates.size() * std::size_t(channels));
  const std::vector<std::int32_t> pixels = pixelsOfCoordinates(coordinates, image.width, image.height);
  for (std::size_t v = 0; v < pixels.size(); ++v)
    std::copy_n(image.pixels.data() + std::size_t(pixels[v]) * channels, channels, colors.data() + v * channels);

  // The exemplar's neighbourhoods of the stencil's size, h apart, at every other pixel.
  std::vector<double> exemplarSpread;
  for (int y = 0; y < image.height; y += 2)
    for (int x = 0; x < image.width; x += 2) {
      Spread spread(channels);
      for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx)
          spread.add(image.pixel(wrapIndex(x + dx * h, image.width), wrapIndex(y + dy * h, image.height)));
      exemplarSpread.push_back(spread.deviation());
    }
  const std::size_t tenth = exemplarSpread.size() / 10;
  std::nth_element(exemplarSpread.begin(), exemplarSpread.begin() + std::ptrdiff_t(tenth), exemplarSpread.end());
  const double threshold = exemplarSpread[tenth];

  std::vector<std::uint8_t> flat(coordinates.size(), 0);
  parallelForChunks(0, std::int64_t(coordinates.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      Spread spread(channels);
      for (const NeighborhoodMember& m : stencil.of(std::size_t(v)))
        spread.add(colors.data() + std::size_t(m.vertex) * channels);
      flat[std::size_t(v)] = spread.deviation() < threshold;
    }
  });
  SurfaceLevelMeasures measures;
  std::size_t flatCount = 0;
  for (std::uint8_t f : flat) flatCount += f;
  measures.flatness = coordinates.empty() ? 0.0 : double(flatCount) / double(coordinates.size()) - 0.10;

  // Distinctive colors: farther from the per-channel median than the exemplar's 80th percentile.
  const std::size_t pixelCount = std::size_t(image.width) * image.height;
  std::vector<float> median(static_cast<std::size_t>(channels)), values(pixelCount);
  for (int c = 0; c < channels; ++c) {
    for (std::size_t p = 0; p < pixelCount; ++p) values[p] = image.pixels[p * channels + std::size_t(c)];
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(pixelCount / 2), values.end());
    median[std::size_t(c)] = values[pixelCount / 2];
  }
  auto fromMedian = [&](const float* color) {
    float sum = 0;
    for (int c = 0; c < channels; ++c) sum += (color[c] - median[std::size_t(c)]) * (color[c] - median[std::size_t(c)]);
    return sum;
  };
  for (std::size_t p = 0; p < pixelCount; ++p) values[p] = fromMedian(image.pixels.data() + p * channels);
  const std::size_t fifth = pixelCount * 4 / 5;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(fifth), values.end());
  const float far = values[fifth];
  std::size_t distinctive = 0;
  for (std::size_t v = 0; v < coordinates.size(); ++v) distinctive += fromMedian(colors.data() + v * channels) > far;
  measures.distinctive = coordinates.empty() ? 0.0 : double(distinctive) / double(coordinates.size());

  // Wasserstein-1 per channel between the sorted vertex values and the sorted exemplar values,
  // compared at matching quantiles.
  const std::size_t n = coordinates.size(), m = std::size_t(image.width) * image.height;
  if (n == 0) return measures;
  std::vector<float> ours(n), theirs(m);
  double total = 0;
  for (int c = 0; c < channels; ++c) {
    for (std::size_t v = 0; v < n; ++v) ours[v] = colors[v * channels + std::size_t(c)];
    for (std::size_t p = 0; p < m; ++p) theirs[p] = image.pixels[p * channels + std::size_t(c)];
    std::sort(ours.begin(), ours.end());
    std::sort(theirs.begin(), theirs.end());
    double sum = 0;
    for (std::size_t v = 0; v < n; ++v) sum += std::abs(ours[v] - theirs[std::min(m - 1, (2 * v + 1) * m / (2 * n))]);
    total += sum / double(n);
  }
  measures.histogram = total / channels;
  return measures;
}

}  // namespace texsynth
