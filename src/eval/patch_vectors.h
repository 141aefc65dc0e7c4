#pragma once
// Internal: patches as vectors in a PCA basis. A patch's vector lists its values row by row,
// pixel by pixel, channel by channel; it is centred on the mean patch and rotated so that
// coordinate 0 carries the most variance. Vectors are padded with zeros to a multiple of
// kLaneWidth floats so distance kernels can work in fixed-width blocks.
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth::eval_detail {

inline constexpr int kLaneWidth = 8;

struct PatchBasis {
  int patchSize = 0;
  int dimensions = 0;           // patchSize * patchSize * channels
  int stride = 0;               // dimensions rounded up to kLaneWidth
  std::vector<float> mean;      // dimensions
  std::vector<float> rotation;  // dimensions x stride, row-major; column j = j-th principal axis
};

// PCA of the patches of `image` (a fixed, evenly strided subsample when there are many):
// deterministic, computed in double, axes sorted by decreasing variance.
PatchBasis computePatchBasis(const Image& image, int patchSize);

// Rotated vectors of the patches whose top-left corner lies in rows [firstRow, firstRow +
// rowCount), all columns, row-major; writes rowCount * columns * stride floats to `out`.
void rotatePatchRows(const Image& image, const PatchBasis& basis, int firstRow, int rowCount, float* out);

// Rotated vector of the single patch at top-left (x, y); writes stride floats to `out`.
void rotatePatch(const Image& image, const PatchBasis& basis, int x, int y, float* out);

// Rotated vectors of `count` patches given as raw values (dimensions floats each, in the patch
// vector layout above); writes count * stride floats to `out`.
void rotateVectors(const float* values, std::size_t count, const PatchBasis& basis, float* out);

}  // namespace texsynth::eval_detail
