#pragma once
// Building blocks of histogram-preserving tiling and blending (Heitz & Neyret 2018), shared
// with the 3D analogue: the skewed triangle-grid lookup and the variance-preserving blend of
// Gaussianized values.
#include <cmath>
#include <cstdint>

namespace texsynth {

// The triangle of the grid that contains a point, with its three lattice vertices and
// barycentric weights (each in [0, 1], summing to 1).
struct GridTriangle {
  std::int64_t vertexI[3], vertexJ[3];
  float weight[3];
};

// Equilateral triangle grid with unit edge: lattice vertex (i, j) lies at
// i * (1, 0) + j * (1/2, sqrt(3)/2). (x, y) is in units of the edge length.
inline GridTriangle triangleGridLookup(double x, double y) {
  constexpr double kInvSqrt3 = 0.57735026918962576;
  // Skew into lattice coordinates, where each unit square holds two triangles.
  double s = x - y * kInvSqrt3, t = 2.0 * y * kInvSqrt3;
  double fi = std::floor(s), fj = std::floor(t);
  double a = s - fi, b = t - fj;
  std::int64_t i = std::int64_t(fi), j = std::int64_t(fj);
  GridTriangle tri;
  if (a + b < 1.0) {
    tri = {{i, i + 1, i}, {j, j, j + 1}, {float(1.0 - a - b), float(a), float(b)}};
  } else {
    tri = {{i + 1, i, i + 1}, {j + 1, j + 1, j}, {float(a + b - 1.0), float(1.0 - a), float(1.0 - b)}};
  }
  return tri;
}

// Sharpens blend weights: w_i^exponent, renormalized to sum 1 (exponent 1 leaves them).
// Higher exponents shrink the blended zones (less ghosting, more visible tile borders).
inline void sharpenWeights(float* weights, int count, float exponent) {
  if (exponent == 1.0f) return;
  float sum = 0;
  for (int k = 0; k < count; ++k) sum += weights[k] = std::pow(weights[k], exponent);
  for (int k = 0; k < count; ++k) weights[k] /= sum;
}

// Variance-preserving blend (Heitz & Neyret 2018, eq. 6):
//   out = sum_k w_k (value_k - mean) / sqrt(sum_k w_k^2) + mean,
// per channel; values[k] points at `channels` values of contribution k. Weights must not all
// be zero. Blending i.i.d. Gaussians this way keeps their mean and variance.
inline void varianceBlend(const float* const* values, const float* weights, int count, int channels, float mean,
                          float* out) {
  float sumSquares = 0;
  for (int k = 0; k < count; ++k) sumSquares += weights[k] * weights[k];
  const float norm = 1.0f / std::sqrt(sumSquares);
  for (int c = 0; c < channels; ++c) {
    float sum = 0;
    for (int k = 0; k < count; ++k) sum += weights[k] * (values[k][c] - mean);
    out[c] = sum * norm + mean;
  }
}

}  // namespace texsynth
