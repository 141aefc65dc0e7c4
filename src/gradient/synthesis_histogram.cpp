// Control-point histogram matching (see synthesis_histogram.h).
#include "synthesis_histogram.h"

#include <algorithm>
#include <vector>

namespace texsynth::gradient_synthesis {
namespace {

constexpr int kQuantiles = 64;     // knots of the piecewise-linear transfer
constexpr float kMaxSlope = 8.0f;  // a transfer steeper than this would turn noise into texture

// The value of `sorted` at quantile q in [0, 1].
float quantile(const std::vector<float>& sorted, double q) {
  const double position = q * double(sorted.size() - 1);
  const std::size_t below = std::size_t(position);
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const float t = float(position - double(below));
  return sorted[below] + t * (sorted[above] - sorted[below]);
}

}  // namespace

void matchControlHistograms(GradientSolid& state, const Image& target) {
  const std::size_t setSize = std::size_t(state.setSize());
  // Every feature set: the positive ones and, with regions, the negative ones.
  std::vector<float*> sets;
  for (std::size_t k = 0; k < state.positive.size(); k += setSize) sets.push_back(&state.positive[k]);
  for (std::size_t k = 0; k < state.negative.size(); k += setSize) sets.push_back(&state.negative[k]);
  for (int c = 0; c < std::min(state.channels, target.channels); ++c) {
    std::vector<float> from(sets.size()), to(target.pixelCount());
    for (std::size_t k = 0; k < sets.size(); ++k) from[k] = sets[k][c];
    for (std::size_t p = 0; p < to.size(); ++p) to[p] = target.pixels[p * target.channels + std::size_t(c)];
    std::sort(from.begin(), from.end());
    std::sort(to.begin(), to.end());
    float x[kQuantiles + 1], y[kQuantiles + 1];
    for (int k = 0; k <= kQuantiles; ++k) {
      x[k] = quantile(from, double(k) / kQuantiles);
      y[k] = quantile(to, double(k) / kQuantiles);
    }
    for (float* set : sets) {
      const float v = set[c];
      const int knot = int(std::upper_bound(x, x + kQuantiles + 1, v) - x) - 1;
      const int i = std::clamp(knot, 0, kQuantiles - 1);
      const float width = x[i + 1] - x[i];
      const float slope = width > 1e-6f ? std::min((y[i + 1] - y[i]) / width, kMaxSlope) : 0.0f;
      set[c] = width > 1e-6f ? std::clamp(y[i] + slope * (v - x[i]), y[0], y[kQuantiles]) : y[i];
      for (int g = 1; g < 4; ++g) set[std::size_t(g * state.channels + c)] *= width > 1e-6f ? slope : 1.0f;
    }
  }
}

}  // namespace texsynth::gradient_synthesis
