#pragma once
// Baselines for the gradient-solid table (bench/gradient_table.cpp): what else the same bytes buy.
#include <cstdint>
#include <string>

#include "texsynth/core/volume.h"

namespace texsynth::bench {

struct BaselineResult {
  double rms = 0;           // 0..255, over all voxels and the first `channels` channels
  double seconds = 0;       // encoding only (downsampling / zfp compression)
  std::uint64_t bytes = 0;  // what the baseline actually stores
  std::string setting;      // the grid size or the zfp rate, for the table's notes
};

// Root mean square difference of the first `channels` channels, on the 0..255 scale.
double volumeRms(const Volume& a, const Volume& b, int channels);

// (a) Box-downsampled to the largest grid whose 8-bit values fit in `bytes`, rounded to 8 bits, then
// upsampled back with Catmull-Rom (Keys a = -1/2) tricubic filtering, clamped at the edges.
BaselineResult downsampleBaseline(const Volume& volume, int channels, std::uint64_t bytes);

// (b) zfp fixed-rate mode at bits per value = 8 bytes / values (rounded down to zfp's 1/64 step in
// 3D), each channel compressed as its own 3D float array.
BaselineResult zfpBaseline(const Volume& volume, int channels, std::uint64_t bytes);

}  // namespace texsynth::bench
