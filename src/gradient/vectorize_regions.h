#pragma once
// Internal to vectorization: region separation (gradient-solid-textures §3.2, §4.3).
#include <cstdint>
#include <vector>

#include "texsynth/core/volume.h"
#include "vectorize_layout.h"

namespace texsynth::vectorize_detail {

struct Regions {
  Volume signedDistance;                    // voxels, positive inside the mask, clamped
  std::vector<CubeSides> cubeSides;         // per cube
  std::vector<std::int32_t> negativeIndex;  // per control: its negative set, or -1
  std::int64_t negatives = 0;
  Volume positive, negative;  // each side's values carried across the boundary
};

// The cubes the mask's boundary crosses, their corners' second sets, and the dilated targets.
Regions separateRegions(const ControlGrid& grid, const Volume& colors, const Volume& mask);

}  // namespace texsynth::vectorize_detail
