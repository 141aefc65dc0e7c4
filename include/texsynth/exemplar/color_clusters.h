#pragma once
// Vector quantization of an exemplar's colours into a few clusters (gradient-solid-textures §4.2.2):
// synthesis counts, per voxel, the samples of each cluster and averages only the dominant ones, so it
// never blurs two different materials together. With two regions (a binary feature mask), clusters
// never span both: each region starts with one, and every further cluster goes to the region whose
// mean quantization error is largest.
#include <cstdint>
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth {

struct ColorClusters {
  int count = 0;                      // clusters
  int channels = 0;                   // of the clustered colours
  std::vector<float> centers;         // count x channels
  std::vector<std::uint8_t> labels;   // per pixel, its cluster
  std::vector<std::uint8_t> regions;  // per cluster, the region it serves (0 without regions)
  double meanSquaredError = 0;        // over all pixels
};

// Clusters the first `channels` channels of every pixel of `image` (all when channels is 0) into
// `count` clusters (1 to 255). `regions`: empty, or one 0/1 label per pixel. Deterministic: clusters
// grow by splitting the worst one at its farthest pixel, then Lloyd iterations, in pixel order.
// Throws ParameterError for an empty image, a bad count or channel count, a regions size mismatch or
// fewer clusters than regions present.
ColorClusters clusterColors(const Image& image, int count, const std::vector<std::uint8_t>& regions = {},
                            int channels = 0);

}  // namespace texsynth
