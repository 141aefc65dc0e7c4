#pragma once
// Image: a 2D grid of float pixels with N interleaved channels, row-major.
// Colors are nominally in [0,1]; 8/16-bit files are normalized on load.
#include <cmath>
#include <cstddef>
#include <vector>

#include "texsynth/core/error.h"

namespace texsynth {

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // size width*height*channels

  Image() = default;
  Image(int width, int height, int channels, float fill = 0.0f);

  bool empty() const { return width == 0 || height == 0 || channels == 0; }
  std::size_t pixelCount() const { return std::size_t(width) * height; }
  std::size_t index(int x, int y) const { return (std::size_t(y) * width + x) * channels; }

  float& at(int x, int y, int c) { return pixels[index(x, y) + c]; }
  float at(int x, int y, int c) const { return pixels[index(x, y) + c]; }
  float* pixel(int x, int y) { return &pixels[index(x, y)]; }
  const float* pixel(int x, int y) const { return &pixels[index(x, y)]; }

  // Toroidal access: coordinates wrap around (exemplars are treated as tileable).
  float wrapped(int x, int y, int c) const;
  // Bilinear lookup at continuous coordinates (pixel centers at integer+0.5), wrapping. Inline
  // for synthesis hot paths; the wrap is done once in double so coordinates far from the origin
  // (random access into an infinite texture) keep their precision.
  void sampleBilinearWrapped(double x, double y, float* out) const {
    double fx = x - 0.5, fy = y - 0.5;
    fx -= std::floor(fx / width) * width;
    fy -= std::floor(fy / height) * height;
    int x0 = int(fx), y0 = int(fy);
    const float tx = float(fx - x0), ty = float(fy - y0);
    if (x0 >= width) x0 -= width;  // fx may round up to exactly width
    if (y0 >= height) y0 -= height;
    const int x1 = x0 + 1 == width ? 0 : x0 + 1, y1 = y0 + 1 == height ? 0 : y0 + 1;
    const float *p00 = pixel(x0, y0), *p10 = pixel(x1, y0), *p01 = pixel(x0, y1), *p11 = pixel(x1, y1);
    for (int c = 0; c < channels; ++c) {
      float top = p00[c] + (p10[c] - p00[c]) * tx;
      float bottom = p01[c] + (p11[c] - p01[c]) * tx;
      out[c] = top + (bottom - top) * ty;
    }
  }

  // The w x h window whose top-left is (x, y); it must lie inside the image.
  Image crop(int x, int y, int w, int h) const;
  // A w x h image filled by repeating this one from the origin (a periodic tiling).
  Image tiled(int w, int h) const;

  // The first `count` channels starting at `first`, as a new image.
  Image channelRange(int first, int count) const;
  // Converts to the requested channel count (gray<->RGB, drop/add alpha=1).
  Image withChannels(int count) const;
};

}  // namespace texsynth
