#pragma once
// Internal: patches as vectors in a PCA basis. A patch's vector lists its values row by row,
// pixel by pixel, channel by channel; it is centred on the mean patch and rotated so that
// coordinate 0 carries the most variance. Vectors are padded with zeros to a multiple of
// kLaneWidth floats so distance kernels can work in fixed-width blocks.
//
// The PCA is only worth it when there are many more patches than dimensions. Its
// eigendecomposition costs ~D^3 and rotating a vector D^2 for D = patchSize^2 * channels
// dimensions (D = 1323 for 21x21 RGB patches), while comparing one query with all n indexed
// patches costs n*D; with few patches of many dimensions (large patches on a small image or a
// volume slice) the PCA alone costs more than searching every patch for every query. Then
// the basis is the identity (raw coordinates): distances stay exact, the tree prunes less.
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth::eval_detail {

inline constexpr int kLaneWidth = 8;

struct PatchBasis {
  int patchSize = 0;
  int dimensions = 0;           // patchSize * patchSize * channels
  int stride = 0;               // dimensions rounded up to kLaneWidth
  std::vector<float> mean;      // dimensions
  std::vector<float> rotation;  // dimensions x stride, row-major; column j = j-th principal axis;
                                // empty: the identity (raw coordinates, see above)
  bool identity() const { return rotation.empty(); }
};

// Whether a PCA basis pays for itself on `patches` indexed patches of `dimensions` values
// (see above); computePatchBasis uses the identity when it does not.
bool pcaPaysOff(std::size_t patches, int dimensions);

// PCA of the patches of `image` (a fixed, evenly strided subsample when there are many):
// deterministic, computed in double, axes sorted by decreasing variance; or the identity when
// the PCA would cost more than it saves.
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
