// The least-squares E-step and KD-tree M-step of texture optimization (Kwatra et al. 2005).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "optimization_steps.h"
#include "texsynth/core/parallel.h"

namespace texsynth::detail {

std::int64_t matchLeastSquares(const OptimizationGrid& grid, const PcaBasis& pca,
                               const ProjectedNeighborhoodIndex& index, const Image& colors, Matches& matches) {
  TS_CHECK(pca.inputDimension == grid.dimension());
  std::vector<std::int64_t> changedPerRow(std::size_t(grid.activeHeight()), 0);
  parallelForChunks(0, grid.activeHeight(), 2, [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> query(static_cast<std::size_t>(grid.dimension()));
    std::vector<float> projected(static_cast<std::size_t>(pca.outputDimension));
    std::vector<int> columns(std::size_t(grid.size));
    auto colorAt = [&](int x, int y) { return colors.pixel(x, y); };
    for (int ay = int(begin); ay < int(end); ++ay)
      for (int ax = 0; ax < grid.activeWidth(); ++ax) {
        grid.gatherOutput(ax * grid.stride, ay * grid.stride, colorAt, query.data());
        pca.project(query.data(), projected.data());
        const std::int32_t found = index.nearest(projected.data());
        const std::int64_t a = std::int64_t(ay) * grid.activeWidth() + ax;
        if (found != matches.pixel[a]) ++changedPerRow[ay];
        matches.pixel[a] = found;
        matches.distance[a] =
            grid.distance(query.data(), found, std::numeric_limits<float>::infinity(), columns.data());
      }
  });
  std::int64_t changed = 0;
  for (std::int64_t c : changedPerRow) changed += c;
  return changed;
}

Image updateLeastSquares(const OptimizationGrid& grid, const Matches& matches, float robustExponent) {
  // w_p = |x_p - z_p|^(r-2) from the squared distance; the floor keeps a perfect match's
  // weight finite (Kwatra et al. use the same IRLS reweighting).
  constexpr float kDistanceFloor = 1e-6f;
  const float power = (robustExponent - 2.0f) * 0.5f;
  std::vector<float> weights(matches.distance.size());
  for (std::size_t a = 0; a < weights.size(); ++a)
    weights[a] = std::pow(std::max(matches.distance[a], kDistanceFloor), power);
  const int channels = grid.channels();
  Image out(grid.width, grid.height, channels);
  parallelForChunks(0, grid.height, 8, [&](std::int64_t begin, std::int64_t end) {
    std::vector<double> sum(static_cast<std::size_t>(channels));
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < grid.width; ++x) {
        std::fill(sum.begin(), sum.end(), 0.0);
        double total = 0;
        grid.forEachCovering(x, y, [&](std::int64_t a, int dx, int dy) {
          const float* color = grid.exemplarColor(grid.shifted(matches.pixel[a], dx, dy));
          for (int c = 0; c < channels; ++c) sum[c] += double(weights[a]) * color[c];
          total += weights[a];
        });
        float* target = out.pixel(x, y);
        for (int c = 0; c < channels; ++c) target[c] = float(sum[c] / total);
      }
  });
  return out;
}

}  // namespace texsynth::detail
