#pragma once
// How evenly a discrete texture optimization's output (an image or mesh vertices) uses the exemplar (an index
// histogram, as in Chen & Wang 2010's index histogram matching). The plain energy has optima
// that leave parts of the exemplar out: thin dark gaps lose the E-step's vote to the stones
// around them, and a flat region copied everywhere costs nothing at all. The usage term makes
// an over-used exemplar region cost more and an unused one less in the M-step. (In the E-step,
// where every pixel moves at once, it makes whole regions jump to the same unused place: GIMP
// corkboard turned flat.)
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/image/exemplar_window.h"

namespace texsynth::detail {

// sigma: the mean Euclidean distance of the level's colors from their mean color, the unit the
// usage and histogram terms speak in whatever the exemplar's contrast.
float colorSpread(const ExemplarWindow& grid);

class UsageMap {
 public:
  UsageMap() = default;
  // Usage of every exemplar pixel by the output's sources (exemplar pixel indices), smoothed over a box of
  // about a quarter of the level's neighborhood footprint (so it speaks of regions, not of
  // single pixels) and divided by its mean: 1 = used as often as uniform coverage would.
  UsageMap(const ExemplarWindow& window, std::span<const std::int32_t> sources, float weight);

  bool active() const { return weight_ > 0; }
  // The term's cost per pixel at exemplar pixel `pixel`: weight * sigma *
  // (usage - 1), where sigma is the exemplar's mean color distance from its mean, so the term
  // speaks in the same units as the energy whatever the exemplar's contrast. Negative for an
  // under-used pixel.
  float cost(std::int32_t pixel) const { return weight_ ? scale_ * relativeUsage_[std::size_t(pixel)] : 0.0f; }
  // weight * sigma: what cost() multiplies usage - 1 by.
  float scale() const { return scale_; }

 private:
  float weight_ = 0, scale_ = 0;
  std::vector<float> relativeUsage_;  // usage / mean - 1, per exemplar pixel
};

}  // namespace texsynth::detail
