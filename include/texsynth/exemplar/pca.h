#pragma once
// PCA of neighborhood vectors: the principal axes of all N x N neighborhoods of a stack
// level, so matching runs on ~20 floats instead of N*N*C (Lefebvre & Hoppe 2005; the
// sketch-guided solid paper reduces "to about 20 dimensions per plane").
#include <cstdint>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/exemplar/neighborhood.h"

namespace texsynth {

struct PcaBasis {
  int inputDimension = 0;   // N*N*C
  int outputDimension = 0;  // D actually kept: min(requested D, inputDimension)
  std::vector<float> mean;  // inputDimension
  // inputDimension x outputDimension, row-major: basis[j*D + i] is input coordinate j's
  // weight in output i. Stored this way so projection streams each row once and the inner
  // loop over the D outputs vectorizes.
  std::vector<float> basis;
  std::vector<float> variances;  // outputDimension, descending: the variance along each axis
  double totalVariance = 0;      // sum of the variances of all inputDimension axes
  double keptEnergy = 1;         // sum(variances) / totalVariance, in (0, 1]; 1 if totalVariance is 0

  float component(int output, int input) const { return basis[std::size_t(input) * outputDimension + output]; }

  // out[D] = basis^T (neighborhood - mean). Bitwise identical to the vectors that analysis
  // stores for the exemplar, so synthesized and exemplar neighborhoods compare exactly.
  void project(const float* neighborhood, float* out) const;
  // Projects `count` neighborhoods stored back to back (count * inputDimension floats).
  void projectMany(const float* neighborhoods, std::int64_t count, float* out) const;
};

// Fits the PCA of all neighborhoods (one per pixel) of `level` with the given shape,
// keeping at most `maxDimensions` axes. The covariance is accumulated in fixed pixel blocks
// and summed in a fixed order, so the basis never depends on the thread count. Each axis's
// sign is fixed (its largest-magnitude weight is positive) so results are reproducible.
PcaBasis fitNeighborhoodPca(const Image& level, const NeighborhoodShape& shape, int maxDimensions);

// The projected neighborhood of every pixel of `level`: pixelCount x basis.outputDimension floats.
std::vector<float> projectAllNeighborhoods(const Image& level, const NeighborhoodShape& shape, const PcaBasis& basis);

}  // namespace texsynth
