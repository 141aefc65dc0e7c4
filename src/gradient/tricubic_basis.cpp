#include "texsynth/gradient/tricubic_basis.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {

TricubicWeightTable::TricubicWeightTable(int samplesPerSide) : samples_(samplesPerSide) {
  if (samplesPerSide < 2 || samplesPerSide > 257)
    throw ParameterError("samplesPerSide", "must be in [2, 257], got " + std::to_string(samplesPerSide));
  table_.resize(std::size_t(samples_) * samples_ * samples_ * kTricubicWeights);
  const float step = 1.0f / float(samples_ - 1);
  for (int i = 0; i < samples_; ++i) {
    const std::array<float, 4> h = hermiteBasis(i * step);
    axes_.insert(axes_.end(), h.begin(), h.end());
  }
  for (int k = 0; k < samples_; ++k)
    for (int j = 0; j < samples_; ++j)
      for (int i = 0; i < samples_; ++i)
        tricubicWeights(i * step, j * step, k * step, const_cast<float*>(entry(i, j, k)));
}

void TricubicWeightTable::weights(float u, float v, float w, float* out) const {
  // Every entry is a product of one Hermite function per axis, so trilinear interpolation of the
  // entries equals the product of linear interpolations of the axes' sampled functions: the same
  // numbers as the 3D fetch, from 3 x 2 x 4 table values instead of 8 x 32.
  tricubicWeights(axisFunctions(u), axisFunctions(v), axisFunctions(w), out);
}

void TricubicWeightTable::weightsFromEntries(float u, float v, float w, float* out) const {
  const float scale = float(samples_ - 1);
  int base[3];
  float frac[3];
  const float t[3] = {u, v, w};
  for (int a = 0; a < 3; ++a) {
    const float s = std::clamp(t[a], 0.0f, 1.0f) * scale;
    base[a] = std::min(int(s), samples_ - 2);
    frac[a] = s - float(base[a]);
  }
  std::fill(out, out + kTricubicWeights, 0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
    const float weight = (dx ? frac[0] : 1 - frac[0]) * (dy ? frac[1] : 1 - frac[1]) * (dz ? frac[2] : 1 - frac[2]);
    const float* e = entry(base[0] + dx, base[1] + dy, base[2] + dz);
    for (int n = 0; n < kTricubicWeights; ++n) out[n] += weight * e[n];
  }
}

}  // namespace texsynth
