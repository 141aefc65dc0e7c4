#pragma once
// Color histogram matching as a term of a discrete M-step (Kopf et al. 2007, section 3.3, on
// exemplar pixels rather than voxels): a candidate whose colors are over-represented in the
// output costs more, an under-represented one less. The usage map (exemplar_usage.h) evens out
// WHERE the exemplar is copied from, region by region; it cannot see that a correction pass
// everywhere prefers the background just beside a thin dark vein to the vein itself, which
// empties the dark tail of the histogram (GIMP pink marble on CGAL meshes: the 5th percentile
// of green 178 against the exemplar's 166). This term sees exactly that.
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth::detail {

class ColorHistogramCost {
 public:
  ColorHistogramCost() = default;
  // Histograms of the first min(3, colorChannels) channels of `image` (kBins bins per channel
  // between the channel's least and greatest value in the image) over all its pixels and over
  // `sources` (pixel indices of the output, one per output element).
  ColorHistogramCost(const Image& image, int colorChannels, std::span<const std::int32_t> sources);

  static constexpr int kBins = 32;

  bool active() const { return !cost_.empty(); }
  // Mean over the channels of (output share / exemplar share - 1) of the bins of `pixel`'s
  // colors, clamped to [-1, 2]: 0 where the output matches the exemplar, positive where that
  // color is over-represented. Dimensionless: the caller scales it into its energy's units.
  float cost(std::int32_t pixel) const { return cost_[std::size_t(pixel)]; }

 private:
  std::vector<float> cost_;  // per exemplar pixel
};

}  // namespace texsynth::detail
