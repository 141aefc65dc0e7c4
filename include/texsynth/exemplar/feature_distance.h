#pragma once
// Feature channel from a binary mask: the exact toroidal signed Euclidean distance to the
// feature boundary (Felzenszwalb & Huttenlocher 2012 lower-envelope passes), normalized and
// weighted, so neighborhood matching sees *where* features are, not just their color.
#include "texsynth/core/image.h"

namespace texsynth {

// Exact toroidal signed distance, in pixels, between pixel centers: for a background pixel
// the distance to the nearest feature pixel (> 0), for a feature pixel minus the distance to
// the nearest background pixel (< 0). A pixel is a feature pixel when any of the mask's
// channels is nonzero. Throws ParameterError if the mask is empty or has no feature pixel or
// no background pixel (the distance would be undefined).
Image signedDistanceToFeature(const Image& mask);

// The feature channel appended to exemplar levels: weight * sdf / max|sdf|, in
// [-weight, weight]. Throws ParameterError for a negative or non-finite weight.
Image featureChannelFromMask(const Image& mask, float weight);

// A copy of `image` with the single channel of `extra` appended as its last channel.
// Throws ParameterError if the sizes differ or `extra` has more than one channel.
Image appendChannel(const Image& image, const Image& extra);

}  // namespace texsynth
