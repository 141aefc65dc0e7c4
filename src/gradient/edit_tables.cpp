#include "edit_tables.h"

#include <algorithm>

#include "texsynth/core/error.h"

namespace texsynth {

InfluenceTables::InfluenceTables(const EditInfluence& influence, const Vec3i& counts, float step)
    : colorChannels_(influence.colorChannels), alpha_(influence.alpha) {
  std::vector<std::size_t> active;
  for (std::size_t k = 0; k < influence.weights.size(); ++k)
    if (influence.weights[k] > 0) active.push_back(k);
  if (active.empty()) return;
  const int n = int((active.size() + kEditLanes - 1) / kEditLanes * kEditLanes);
  padded_ = n;
  // Padding lanes get weight 0 (so h 0) and neutral, finite table entries.
  weights_.assign(std::size_t(n), 0.0f);
  for (int a = 0; a < 3; ++a) {
    centre_[a].assign(std::size_t(n), 0.0f);
    centreColor_[a].assign(std::size_t(n), 0.0f);
  }
  for (std::size_t s = 0; s < active.size(); ++s) {
    weights_[s] = float(influence.weights[active[s]]);
    for (int a = 0; a < 3; ++a) {
      centre_[a][s] = influence.centres[active[s]][a];
      centreColor_[a][s] = influence.centreColors[active[s]][std::size_t(a)];
    }
  }
  const double ab = double(influence.alpha) * double(influence.beta);
  for (int a = 0; a < 3; ++a) {
    TS_CHECK(counts[a] >= 1);
    axis_[a].assign(std::size_t(counts[a]) * std::size_t(n), 0.0f);
    for (int i = 0; i < counts[a]; ++i)
      for (std::size_t s = 0; s < active.size(); ++s) {
        const double d = double(i) * double(step) - double(centre_[a][s]);
        axis_[a][std::size_t(i) * std::size_t(n) + s] = float(std::exp(-ab * d * d));
      }
  }
  resolution_ = std::clamp(int(std::ceil(std::sqrt(double(alpha_) / 4e-4))), 1, 16);
  const int values = (kHighest - kLowest) * resolution_ + 1;
  for (int c = 0; c < colorChannels_; ++c) {
    color_[c].assign(std::size_t(values) * std::size_t(n), 0.0f);
    for (int q = 0; q < values; ++q)
      for (std::size_t s = 0; s < active.size(); ++s) {
        const double d = double(kLowest) + double(q) / resolution_ - double(centreColor_[c][s]);
        color_[c][std::size_t(q) * std::size_t(n) + s] = float(std::exp(-double(alpha_) * d * d));
      }
  }
}

void InfluenceTables::rowFactors(int j, int l, float* out) const {
  const float* y = &axis_[1][std::size_t(j) * std::size_t(padded_)];
  const float* z = &axis_[2][std::size_t(l) * std::size_t(padded_)];
  for (int k = 0; k < padded_; ++k) out[k] = weights_[std::size_t(k)] * y[k] * z[k];
}

void InfluenceTables::exactColorTerms(const float* color255, float* out) const {
  for (int k = 0; k < padded_; ++k) {
    double distance = 0;
    for (int c = 0; c < colorChannels_; ++c) {
      const double d = double(color255[c]) - double(centreColor_[c][std::size_t(k)]);
      distance += d * d;
    }
    out[k] = float(std::exp(-double(alpha_) * distance));
  }
}

}  // namespace texsynth
