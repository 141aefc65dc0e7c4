// The least-squares E-step and KD-tree M-step of texture optimization (Kwatra et al. 2005), and
// the colors of a map of sources.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "optimization_steps.h"
#include "texsynth/core/parallel.h"

namespace texsynth::detail {

std::int64_t matchLeastSquares(const OptimizationGrid& grid, const PcaBasis& pca,
                               const ProjectedNeighborhoodIndex& index, const Image& colors, Matches& matches) {
  const ExemplarWindow& window = grid.window;
  TS_CHECK(pca.inputDimension == window.dimension());
  std::vector<std::uint8_t> changed(matches.pixel.size(), 0);
  parallelForChunks(0, grid.activeCount(), grid.activeChunk(), [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> query(static_cast<std::size_t>(window.dimension()));
    std::vector<float> projected(static_cast<std::size_t>(pca.outputDimension));
    std::vector<int> columns(std::size_t(window.size));
    auto colorOf = [&](std::int64_t sample) { return colors.pixels.data() + std::size_t(sample) * colors.channels; };
    for (std::int64_t a = begin; a < end; ++a) {
      grid.gather(a, colorOf, query.data());
      pca.project(query.data(), projected.data());
      const std::int32_t found = index.nearest(projected.data());
      changed[std::size_t(a)] = found != matches.pixel[std::size_t(a)];
      matches.pixel[std::size_t(a)] = found;
      matches.distance[std::size_t(a)] =
          window.distance(query.data(), found, std::numeric_limits<float>::infinity(), columns.data());
    }
  });
  std::int64_t total = 0;
  for (std::uint8_t c : changed) total += c;
  return total;
}

Image updateLeastSquares(const OptimizationGrid& grid, const Matches& matches, float robustExponent) {
  // w_p = |x_p - z_p|^(r-2) from the squared distance; the floor keeps a perfect match's
  // weight finite (Kwatra et al. use the same IRLS reweighting).
  constexpr float kDistanceFloor = 1e-6f;
  const float power = (robustExponent - 2.0f) * 0.5f;
  std::vector<float> weights(matches.distance.size());
  for (std::size_t a = 0; a < weights.size(); ++a)
    weights[a] = std::pow(std::max(matches.distance[a], kDistanceFloor), power);
  const ExemplarWindow& window = grid.window;
  const int channels = window.channels();
  Image out(grid.width, grid.height, channels);
  parallelForChunks(0, grid.sampleCount(), grid.sampleChunk(), [&](std::int64_t begin, std::int64_t end) {
    std::vector<double> sum(static_cast<std::size_t>(channels));
    for (std::int64_t sample = begin; sample < end; ++sample) {
      std::fill(sum.begin(), sum.end(), 0.0);
      double total = 0;
      grid.forEachCovering(sample, [&](std::int64_t a, int dx, int dy) {
        const float* color = window.exemplarColor(window.shifted(matches.pixel[std::size_t(a)], dx, dy));
        for (int c = 0; c < channels; ++c) sum[c] += double(weights[std::size_t(a)]) * color[c];
        total += weights[std::size_t(a)];
      });
      float* target = out.pixels.data() + std::size_t(sample) * channels;
      for (int c = 0; c < channels; ++c) target[c] = float(sum[c] / total);
    }
  });
  return out;
}

Image colorsAt(const OptimizationGrid& grid, std::span<const std::int32_t> sources) {
  const ExemplarWindow& window = grid.window;
  const int channels = window.channels();
  Image out(grid.width, grid.height, channels);
  parallelForChunks(0, grid.sampleCount(), grid.sampleChunk(), [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t sample = begin; sample < end; ++sample) {
      const float* color = window.exemplarColor(sources[std::size_t(sample)]);
      std::copy(color, color + channels, out.pixels.data() + std::size_t(sample) * channels);
    }
  });
  return out;
}

}  // namespace texsynth::detail
