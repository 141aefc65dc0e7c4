// The exemplar usage map of texture optimization: counts, a toroidal box blur, normalization.
#include "texsynth/image/exemplar_usage.h"

#include <algorithm>
#include <cmath>

namespace texsynth::detail {
namespace {

// Box blur of radius r along one axis of a width x height torus; `stride` steps along the axis.
void boxBlurAxis(std::vector<float>& values, int width, int height, int radius, bool alongX) {
  const int length = alongX ? width : height, lines = alongX ? height : width;
  const std::size_t step = alongX ? 1 : std::size_t(width);
  std::vector<float> line(static_cast<std::size_t>(length));
  const float norm = 1.0f / float(2 * radius + 1);
  for (int l = 0; l < lines; ++l) {
    float* first = values.data() + (alongX ? std::size_t(l) * width : std::size_t(l));
    for (int i = 0; i < length; ++i) line[std::size_t(i)] = first[std::size_t(i) * step];
    float sum = 0;
    for (int d = -radius; d <= radius; ++d) sum += line[std::size_t(wrapIndex(d, length))];
    for (int i = 0; i < length; ++i) {
      first[std::size_t(i) * step] = sum * norm;
      sum += line[std::size_t(wrapIndex(i + radius + 1, length))] - line[std::size_t(wrapIndex(i - radius, length))];
    }
  }
}

}  // namespace

float colorSpread(const ExemplarWindow& grid) {
  const int c = grid.channels();
  const std::size_t pixels = std::size_t(grid.exemplarWidth) * grid.exemplarHeight;
  std::vector<double> mean(std::size_t(c), 0.0);
  for (std::size_t p = 0; p < pixels; ++p)
    for (int k = 0; k < c; ++k) mean[std::size_t(k)] += grid.exemplarColor(std::int32_t(p))[k];
  for (double& m : mean) m /= double(pixels);
  double spread = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    double d2 = 0;
    for (int k = 0; k < c; ++k) {
      const double d = grid.exemplarColor(std::int32_t(p))[k] - mean[std::size_t(k)];
      d2 += d * d;
    }
    spread += std::sqrt(d2);
  }
  return float(spread / double(pixels));
}

UsageMap::UsageMap(const ExemplarWindow& grid, std::span<const std::int32_t> sources, float weight) : weight_(weight) {
  if (weight_ <= 0) return;
  const int w = grid.exemplarWidth, h = grid.exemplarHeight;
  relativeUsage_.assign(std::size_t(w) * h, 0.0f);
  for (std::int32_t pixel : sources) relativeUsage_[std::size_t(pixel)] += 1.0f;
  const int radius = std::max(1, grid.radius * grid.spacing() / 2);
  boxBlurAxis(relativeUsage_, w, h, std::min(radius, (w - 1) / 2), true);
  boxBlurAxis(relativeUsage_, w, h, std::min(radius, (h - 1) / 2), false);
  const float mean = float(sources.size()) / float(relativeUsage_.size());
  for (float& u : relativeUsage_) u = u / mean - 1.0f;
  scale_ = weight_ * colorSpread(grid);
}

}  // namespace texsynth::detail
