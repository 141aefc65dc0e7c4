#pragma once
// Internal to vectorization: region separation (gradient-solid-textures §3.2, §4.3).
#include <cstdint>
#include <vector>

#include "texsynth/core/volume.h"
#include "vectorize_layout.h"

namespace texsynth::vectorize_detail {

struct Regions {
  std::vector<CubeSides> cubeSides;         // per cube
  std::vector<std::int32_t> negativeIndex;  // per control: its negative set, or -1
  std::int64_t negatives = 0;
  Volume positive, negative;  // each side's values carried across the boundary
};

// The cubes the regions' boundary crosses, their corners' second sets, and the dilated targets. `sides`
// (> 0.5: positive) says which side evaluation puts each voxel on: the sign of the fitted distance.
Regions separateRegions(const ControlGrid& grid, const Volume& colors, const Volume& sides);

}  // namespace texsynth::vectorize_detail
