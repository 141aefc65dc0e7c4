#pragma once
// Internal to the gradient module: eq. 4 evaluated fast on a regular grid of points (control
// points or voxels). exp(-alpha (beta |p - p_k|^2 + |c - c_k|^2)) factors into one term per
// position axis and one per colour channel, so per centre it is a product of table entries:
// positions from per-axis tables over the grid, colours from tables over the 0..255 scale, linearly
// interpolated. |d2/dc2 exp(-alpha c^2)| <= 2 alpha, so steps of 1/r units err by at most
// alpha / (4 r^2) of the peak; r is chosen for 1e-4 (r = 1 at the paper's alpha = 1e-4).
// Centres are padded to a multiple of kEditLanes so the inner loops run on whole vectors; results
// per point never depend on other points, hence not on threads either.
#include <cmath>
#include <vector>

#include "texsynth/gradient/edit_influence.h"

namespace texsynth {

inline constexpr int kEditLanes = 8;

// Sums over the centres at one point, with w_k h_k the weighted RBF: S0 = sum w_k h_k (that is h),
// Sp = sum w_k h_k p_k and Sc = sum w_k h_k c_k (0..255 scale), enough for eq. 6.
struct InfluenceSums {
  float s0 = 0;
  float sp[3] = {0, 0, 0};
  float sc[3] = {0, 0, 0};
};

class InfluenceTables {
 public:
  // Grid point (i, j, l) lies at (i, j, l) * step voxels, for i < counts.x() and so on. Centres
  // with weight 0 are left out: with none left, empty() is true and the edit changes nothing.
  InfluenceTables(const EditInfluence& influence, const Vec3i& counts, float step);
  bool empty() const { return padded_ == 0; }
  int padded() const { return padded_; }

  // w_k * (y and z terms) of row (j, l), padded() floats: the part shared by a row's points.
  void rowFactors(int j, int l, float* out) const;

  // The sums at point i of a row whose factors are `row`, for a colour on the 0..255 scale.
  // Without `moments` only s0 is filled.
  template <bool moments>
  InfluenceSums sums(const float* row, int i, const float* color255) const;

 private:
  static constexpr int kLowest = -256, kHighest = 511;  // table range on the 0..255 scale

  void exactColorTerms(const float* color255, float* out) const;

  int padded_ = 0, colorChannels_ = 3;
  int resolution_ = 1;  // colour table entries per unit of the 0..255 scale
  float alpha_ = 0;
  std::vector<float> weights_, centre_[3], centreColor_[3];  // per padded centre
  std::vector<float> axis_[3];                               // [point][centre] position terms per axis
  std::vector<float> color_[3];                              // [value - kLowest][centre] colour terms
};

template <bool moments>
InfluenceSums InfluenceTables::sums(const float* row, int i, const float* color255) const {
  // Explicit 4-float vectors (SSE2/NEON width): GCC does not vectorize these float reductions alone.
  using Lanes = float __attribute__((vector_size(16)));
  constexpr int kWidth = 4;
  auto load = [](const float* p) {
    Lanes v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  };
  const int n = padded_, cc = colorChannels_;
  // Table rows and interpolation fractions per channel; a colour beyond the tables (overshoot of
  // the tricubic) takes exact terms instead.
  const float* lower[3] = {nullptr, nullptr, nullptr};
  float fraction[3] = {0, 0, 0};
  bool inTables = true;
  const float last = float((kHighest - kLowest) * resolution_);
  for (int c = 0; c < cc; ++c) {
    const float scaled = (color255[c] - float(kLowest)) * float(resolution_);
    if (!(scaled >= 0.0f && scaled < last)) {
      inTables = false;
      break;
    }
    const float floor = std::floor(scaled);
    fraction[c] = scaled - floor;
    lower[c] = &color_[c][std::size_t(floor) * std::size_t(n)];
  }
  std::vector<float> exact;
  if (!inTables) {
    exact.resize(std::size_t(n));
    exactColorTerms(color255, exact.data());
  }
  const float* x = &axis_[0][std::size_t(i) * std::size_t(n)];
  Lanes a0 = {}, ap[3] = {}, ac[3] = {};
  for (int k = 0; k < n; k += kWidth) {
    Lanes h = load(row + k) * load(x + k);
    if (inTables) {
      for (int c = 0; c < cc; ++c) {
        const Lanes t0 = load(lower[c] + k), t1 = load(lower[c] + k + n);
        h *= t0 + fraction[c] * (t1 - t0);
      }
    } else {
      h *= load(exact.data() + k);
    }
    a0 += h;
    if constexpr (moments) {
      for (int a = 0; a < 3; ++a) ap[a] += h * load(centre_[a].data() + k);
      for (int c = 0; c < cc; ++c) ac[c] += h * load(centreColor_[c].data() + k);
    }
  }
  InfluenceSums out;
  for (int l = 0; l < kWidth; ++l) out.s0 += a0[l];
  if constexpr (moments) {
    for (int a = 0; a < 3; ++a)
      for (int l = 0; l < kWidth; ++l) out.sp[a] += ap[a][l];
    for (int c = 0; c < cc; ++c)
      for (int l = 0; l < kWidth; ++l) out.sc[c] += ac[c][l];
  }
  return out;
}

}  // namespace texsynth
