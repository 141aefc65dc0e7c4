#pragma once
// The regular sampling grid over a box that solid slices, sampled volumes and surface voxels
// share: `resolution` voxels along the box's longest side, the other sides proportionally (at
// least 1), samples at voxel centres (axis a, index i at box.min[a] + ((i + 0.5) / n[a]) * size[a]).
#include "texsynth/core/math.h"

namespace texsynth {

// Grid size (x, y, z) for `resolution` voxels along the longest side of `box`.
// Throws ParameterError("box" | "resolution", ...).
Vec3i samplingGridSize(const Box3f& box, int resolution);

}  // namespace texsynth
