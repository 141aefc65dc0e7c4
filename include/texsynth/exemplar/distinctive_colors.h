#pragma once
// Distinctive colors: the ones farther from an image's per-channel median color than all but a
// given share of its pixels. On a flat-background exemplar they are its sparse features (cracks,
// veins, mortar); elsewhere the ends of its color distribution. Surface synthesis counts them
// (its levels must not lose them), and surface and 2D optimization mark them as the exemplar's
// features (their signed distance becomes a feature channel, feature_distance.h).
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth {

class DistinctiveColors {
 public:
  // From the first `channels` channels of `image`: distinctive = farther (squared Euclidean) from
  // the median than the pixel at the (100 - percent)th percentile of those distances.
  DistinctiveColors(const Image& image, int channels, int percent);

  bool operator()(const float* color) const { return squaredDistanceFromMedian(color) > threshold_; }

 private:
  float squaredDistanceFromMedian(const float* color) const;

  std::vector<float> median_;
  int channels_;
  float threshold_ = 0;
};

// The share of an exemplar's pixels that count as distinctive in synthesis: surface synthesis's
// level measures, and the feature channel of surface and 2D optimization.
constexpr int kDistinctivePercent = 20;

// 1 where a pixel of `exemplar` (all its channels) is distinctive at `percent`, 0 elsewhere; an
// empty image where no pixel or every pixel is (a flat exemplar has no features).
Image distinctiveFeatureMask(const Image& exemplar, int percent);

}  // namespace texsynth
