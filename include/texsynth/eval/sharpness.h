#pragma once
// Sharpness: how crisp an image is, as the mean magnitude of its color gradient (forward
// differences, RGB). The metrics report an output's over its exemplar's: 1 = as crisp, below 1
// blurrier (least-squares blending, filtering), above 1 noisier or seamier.
#include "texsynth/core/image.h"

namespace texsynth {

// Mean over the pixels with a right and a lower neighbour of sqrt(|dI/dx|^2 + |dI/dy|^2),
// summed over channels. 0 for images narrower or lower than 2 pixels.
double meanGradientMagnitude(const Image& image);

}  // namespace texsynth
