#pragma once
// Tricubic interpolation with gradients (gradient solids §3.1): inside a cube of the control grid,
// the value at parameter (u,v,w) in [0,1]^3 is a weighted sum of 32 numbers, the value and the three
// gradients at each of the 8 corners, with second and higher mixed derivatives taken as zero.
// The weights are tensor products of the cubic Hermite basis, which is the tricubic of Lekien &
// Marsden with its cross-derivative terms zero: it reproduces corner values and gradients exactly
// and is C1 across cube faces, because a face's values and normal derivatives depend only on the
// face's own corners.
//
// Order of the 32 weights: corner p = x + 2y + 4z (x, y, z in {0,1}), then slot s = 0 value,
// 1 d/du, 2 d/dv, 3 d/dw: weight index 4p + s. Gradients are per cube edge (u runs 0..1 across
// one cube), not per voxel.
#include <algorithm>
#include <array>
#include <vector>

namespace texsynth {

inline constexpr int kTricubicWeights = 32;

// The four cubic Hermite functions at t in [0,1]: {value at 0, value at 1, slope at 0, slope at 1}.
inline std::array<float, 4> hermiteBasis(float t) {
  const float t2 = t * t, t3 = t2 * t;
  return {2 * t3 - 3 * t2 + 1, -2 * t3 + 3 * t2, t3 - 2 * t2 + t, t3 - t2};
}

// Their derivatives d/dt.
inline std::array<float, 4> hermiteBasisDerivative(float t) {
  const float t2 = t * t;
  return {6 * t2 - 6 * t, -6 * t2 + 6 * t, 3 * t2 - 4 * t + 1, 3 * t2 - 2 * t};
}

// The 32 weights at (u,v,w), from the three axes' Hermite functions.
inline void tricubicWeights(const std::array<float, 4>& hu, const std::array<float, 4>& hv,
                            const std::array<float, 4>& hw, float* weights) {
  for (int p = 0; p < 8; ++p) {
    const int x = p & 1, y = (p >> 1) & 1, z = (p >> 2) & 1;
    const float vu = hu[x], vv = hv[y], vw = hw[z];
    weights[4 * p + 0] = vu * vv * vw;
    weights[4 * p + 1] = hu[2 + x] * vv * vw;
    weights[4 * p + 2] = vu * hv[2 + y] * vw;
    weights[4 * p + 3] = vu * vv * hw[2 + z];
  }
}

inline void tricubicWeights(float u, float v, float w, float* weights) {
  tricubicWeights(hermiteBasis(u), hermiteBasis(v), hermiteBasis(w), weights);
}

// The precomputed weights of §3/§5.3: (samples)^3 points per cube, spaced 1/(samples-1) of a cube,
// 32 weights each (33^3 x 32 is 1/8 voxel at spacing 4, about 4.4 MB; 17^3 x 32 is 1/4 voxel, 0.6 MB).
// Lookups interpolate the entries trilinearly, as a GPU's texture fetch does; on the CPU weights()
// gets the same numbers from the table's per-axis factors (see tricubic_basis.cpp).
class TricubicWeightTable {
 public:
  explicit TricubicWeightTable(int samplesPerSide = 33);
  int samplesPerSide() const { return samples_; }
  std::size_t bytes() const { return table_.size() * sizeof(float); }
  // The stored entry at sample (i,j,k), each in [0, samplesPerSide).
  const float* entry(int i, int j, int k) const {
    return &table_[((std::size_t(k) * samples_ + j) * samples_ + i) * kTricubicWeights];
  }
  // Weights at (u,v,w) in [0,1]^3, trilinear between the 8 nearest entries.
  void weights(float u, float v, float w, float* out) const;
  // The table's factor along one axis at t: the 4 Hermite functions interpolated linearly.
  std::array<float, 4> axisFunctions(float t) const {
    const float s = std::clamp(t, 0.0f, 1.0f) * float(samples_ - 1);
    const int i = std::min(int(s), samples_ - 2);
    const float f = s - float(i);
    const float *a = &axes_[std::size_t(i) * 4], *b = a + 4;
    return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]), a[3] + f * (b[3] - a[3])};
  }
  // The same by fetching the 8 entries (the GPU's way; slower on a CPU).
  void weightsFromEntries(float u, float v, float w, float* out) const;

 private:
  int samples_;
  std::vector<float> table_;
  std::vector<float> axes_;  // the 4 Hermite functions at each sample of one axis
};

}  // namespace texsynth
