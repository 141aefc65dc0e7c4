#pragma once
// Image: a 2D grid of float pixels with N interleaved channels, row-major.
// Colors are nominally in [0,1]; 8/16-bit files are normalized on load.
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
  // Bilinear lookup at continuous coordinates (pixel centers at integer+0.5), wrapping.
  void sampleBilinearWrapped(float x, float y, float* out) const;

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
