#pragma once
// How much of a synthesized level is flat: the share of its patches whose colors deviate less
// than the exemplar level's flattest tenth of patches do (about 0.1 for a faithful texture, 1
// for one color everywhere). Texture optimization's collapse detector: the discrete energy's
// flat optimum shows here first, as whole regions of a flat-background exemplar (GIMP cracked)
// lose their fine relief and then their features.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "texsynth/exemplar/analysis.h"

namespace texsynth::detail {

// The RMS difference of a patch's `count` colors colorAt(0..count-1) (pointers to `channels`
// values each) from their mean color, over all values: 0 for a one-color patch. Two passes, four
// channels at a time, so that a bright flat patch reads 0 without cancellation.
template <class ColorAt>
double patchDeviation(int count, int channels, ColorAt&& colorAt) {
  double sum = 0;
  for (int c0 = 0; c0 < channels; c0 += 4) {
    const int c1 = std::min(channels, c0 + 4);
    double mean[4] = {0, 0, 0, 0};
    for (int i = 0; i < count; ++i) {
      const float* color = colorAt(i);
      for (int c = c0; c < c1; ++c) mean[c - c0] += color[c];
    }
    for (double& m : mean) m /= count;
    for (int i = 0; i < count; ++i) {
      const float* color = colorAt(i);
      for (int c = c0; c < c1; ++c) sum += (color[c] - mean[c - c0]) * (color[c] - mean[c - c0]);
    }
  }
  return std::sqrt(sum / (double(channels) * count));
}

// The flatness threshold of an exemplar level: the 10th percentile of the patchDeviation of its
// toroidal patches of side `size` (output pixels, so `spacing` exemplar pixels apart), centred on
// every other pixel, over its first `channels`. A patch below it is flat.
double flatPatchThreshold(const ExemplarLevel& level, int channels, int size);

class FlatPatchShare {
 public:
  // The exemplar side: flatPatchThreshold over the level's first `colorChannels` (at most 4).
  FlatPatchShare(const ExemplarLevel& level, int colorChannels, int size = 7);

  // The share of a toroidal width x height output of sources (exemplar pixel indices, row by
  // row) whose patches, centred on every other pixel in x and y, are flatter than that.
  double of(std::span<const std::int32_t> sources, int width, int height) const;

  double threshold() const { return threshold_; }

 private:
  const ExemplarLevel& level_;
  int channels_, radius_;
  double threshold_ = 0;
};

}  // namespace texsynth::detail
