#pragma once
// How much of a synthesized level is flat: the share of its patches whose colors deviate less
// than the exemplar level's flattest tenth of patches do (about 0.1 for a faithful texture, 1
// for one color everywhere). Texture optimization's collapse detector: the discrete energy's
// flat optimum shows here first, as whole regions of a flat-background exemplar (GIMP cracked)
// lose their fine relief and then their features.
#include <cstdint>
#include <span>

#include "texsynth/exemplar/analysis.h"

namespace texsynth::detail {

class FlatPatchShare {
 public:
  // The exemplar side: the 10th percentile of the deviations of the level's patches of side
  // `size` (output pixels, so `spacing` exemplar pixels apart) over its first `colorChannels`.
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
