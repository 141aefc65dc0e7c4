#pragma once
// Images shared by the eval tests.
#include "texsynth/core/image.h"
#include "texsynth/core/random.h"

namespace texsynth::test {

// The w×h window of `image` at (x0, y0).
// Independent uniform values in [0,1) per pixel and channel.
inline Image noise(int w, int h, std::uint64_t seed, int channels = 3) {
  Image out(w, h, channels);
  for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = uniform01(hashKey(seed, i));
  return out;
}

// Every value times `factor` (to move test images onto the 0..255 scale of the metrics).
inline Image scaled(Image image, float factor) {
  for (float& v : image.pixels) v *= factor;
  return image;
}

}  // namespace texsynth::test
