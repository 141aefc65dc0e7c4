#pragma once
// Slice montage: a quick look inside a volume (a synthesized solid texture) as a grid of
// axis-aligned slices.
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/core/volume.h"

namespace texsynth {

struct MontageOptions {
  // Slice positions, as fractions of each axis in [0, 1]; fraction f picks voxel index
  // min(n - 1, floor(f * n)). One column per fraction; at least one.
  std::vector<float> fractions{0.25f, 0.5f, 0.75f};
  // Background pixels around and between cells; in [0, 1024].
  int border = 4;
  Vec3f background{1, 1, 1};
  // Each voxel becomes scale x scale pixels (nearest neighbour); in [1, 64].
  int scale = 1;
};

// An RGB image of slices. Row 0 holds slices normal to x, row 1 normal to y, row 2 normal to z;
// column c is at fractions[c]. Every cell is max(nx, ny) * scale wide and max(ny, nz) * scale
// tall, the slice drawn at the cell's top-left, the rest background. Within a slice the image
// x axis follows the first remaining volume axis and image y (downwards) the second:
// x-slice (y, z), y-slice (x, z), z-slice (x, y). Cells sit `border` pixels apart and from
// the edges. Volumes with 1 channel show as gray, 3 as RGB, 4 as RGB (alpha ignored); values
// are shown as they are, not rescaled. Throws ParameterError for bad options, an empty
// volume or another channel count.
Image sliceMontage(const Volume& volume, const MontageOptions& options = {});

}  // namespace texsynth
