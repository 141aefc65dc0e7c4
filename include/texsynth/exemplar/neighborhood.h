#pragma once
// Neighborhood vectors: the N x N pixels around a pixel, sampled at a level's spacing h
// (offsets h*d, d in [-N/2, N/2]^2), toroidally, all channels. The layout is the contract
// between analysis and every synthesizer: rows of the window top to bottom, each row left
// to right, each pixel's channels in order (index ((dy+r)*N + (dx+r))*C + c, r = N/2).
#include <cstdint>

#include "texsynth/core/image.h"

namespace texsynth {

// Largest supported N (keeps per-call scratch on the stack).
constexpr int kMaxNeighborhoodSize = 63;

struct NeighborhoodShape {
  int size = 5;      // N, odd, <= kMaxNeighborhoodSize
  int spacing = 1;   // h_l
  int channels = 3;  // C
  int radius() const { return size / 2; }
  int dimension() const { return size * size * channels; }
};

// The neighborhood of `image` around (x, y) (any integers; they wrap) into out[dimension].
void gatherNeighborhood(const Image& image, int x, int y, const NeighborhoodShape& shape, float* out);

// Neighborhoods of `count` consecutive pixels in row-major order starting at pixel index
// `first` (= y*width + x), into out[count * dimension]; faster than one pixel at a time.
void gatherNeighborhoods(const Image& image, std::int64_t first, std::int64_t count, const NeighborhoodShape& shape,
                         float* out);

}  // namespace texsynth
