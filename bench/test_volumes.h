#pragma once
// Stand-ins for the gradient-solid paper's test volumes ('balls' and 'caustics' are not public),
// made deterministically so that bench/gradient_table.sh measures the same voxels everywhere.
#include <cstdint>

#include "texsynth/core/volume.h"

namespace texsynth::bench {

// Non-overlapping shaded spheres of a few colours on a smoothly varying background (Fig. 11's
// kind: sharp region boundaries, smooth inside). `mask` gets 1 inside the spheres, else 0.
Volume makeBallsVolume(int side, std::uint64_t seed, Volume& mask);

// Smooth, colourful caustics-like light patterns (Fig. 10's kind): no sharp edges anywhere.
Volume makeCausticsVolume(int side, std::uint64_t seed);

// 1 where the voxel's luminance is above the volume's median luminance, else 0.
Volume medianLuminanceMask(const Volume& volume);

// 1 where a pixel's (or voxel's) luminance lies above (or below) the given quantile of all of them, else 0:
// `values` holds `channels` floats per element.
std::vector<float> luminanceMask(const std::vector<float>& values, int channels, float quantile, bool above);

}  // namespace texsynth::bench
