#pragma once
// Periodicity: does an image repeat itself at one fixed offset, as a tiling does?
//
// A seeded sample of patch positions is drawn (hashKey(seed, i), with replacement; every
// position instead if there are no more positions than samples). For each sampled patch,
// every near-duplicate elsewhere in the image is found exactly (mean squared difference per
// value <= duplicateThreshold, positions overlapping the sample, |dx| < patch and |dy| <
// patch, excluded) and its offset recorded once per sample. An offset and its opposite are one
// period (a tiling by 128 repeats at +128 and -128 alike), so offsets are counted up to sign.
// Periodicity is the share of samples that have a duplicate at the most common offset: about 1
// for a tiling, 0 for noise, small for good synthesis.
#include <cstdint>

#include "texsynth/core/image.h"
#include "texsynth/eval/patch_index.h"

namespace texsynth {

struct PeriodicityOptions {
  int samples = 2000;               // sampled patch positions (>= 1)
  double duplicateThreshold = 4.0;  // mean squared difference per value for a duplicate (>= 0)
  std::uint64_t seed = 1;
};

// Periodicity of the image that `index` was built from.
double periodicity(const PatchIndex& index, const PeriodicityOptions& options = {});

}  // namespace texsynth
