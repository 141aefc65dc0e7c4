// Region-aware k-means quantization of exemplar colours (see color_clusters.h).
#include "texsynth/exemplar/color_clusters.h"

#include <algorithm>
#include <limits>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

constexpr int kLloydIterations = 12;

struct Clustering {
  const Image* image;
  int channels;
  std::vector<float> centers;
  std::vector<std::uint8_t> regions;  // per cluster

  int clusters() const { return int(regions.size()); }
  float distance(std::size_t pixel, int cluster) const {
    const float* p = image->pixels.data() + pixel * image->channels;
    const float* c = &centers[std::size_t(cluster) * channels];
    float d = 0;
    for (int i = 0; i < channels; ++i) d += (p[i] - c[i]) * (p[i] - c[i]);
    return d;
  }
  // The nearest cluster of the pixel's region.
  int nearest(std::size_t pixel, std::uint8_t region) const {
    int best = -1;
    float bestDistance = std::numeric_limits<float>::max();
    for (int c = 0; c < clusters(); ++c)
      if (regions[std::size_t(c)] == region) {
        const float d = distance(pixel, c);
        if (best < 0 || d < bestDistance) best = c, bestDistance = d;
      }
    return best;
  }
};

std::uint8_t regionOf(const std::vector<std::uint8_t>& regions, std::size_t pixel) {
  return regions.empty() ? 0 : regions[pixel];
}

// Lloyd iterations over all pixels (clusters stay in their regions); returns the labels.
std::vector<std::uint8_t> lloyd(Clustering& k, const std::vector<std::uint8_t>& regions) {
  const std::size_t pixels = k.image->pixelCount();
  std::vector<std::uint8_t> labels(pixels);
  for (int iteration = 0; iteration <= kLloydIterations; ++iteration) {
    for (std::size_t p = 0; p < pixels; ++p) labels[p] = std::uint8_t(k.nearest(p, regionOf(regions, p)));
    if (iteration == kLloydIterations) break;
    std::vector<double> sums(k.centers.size(), 0.0);
    std::vector<double> counts(std::size_t(k.clusters()), 0.0);
    for (std::size_t p = 0; p < pixels; ++p) {
      counts[labels[p]] += 1;
      for (int c = 0; c < k.channels; ++c)
        sums[std::size_t(labels[p]) * k.channels + c] += k.image->pixels[p * k.image->channels + c];
    }
    for (int cluster = 0; cluster < k.clusters(); ++cluster)
      if (counts[std::size_t(cluster)] > 0)
        for (int c = 0; c < k.channels; ++c)
          k.centers[std::size_t(cluster) * k.channels + c] =
              float(sums[std::size_t(cluster) * k.channels + c] / counts[std::size_t(cluster)]);
  }
  return labels;
}

}  // namespace

ColorClusters clusterColors(const Image& image, int count, const std::vector<std::uint8_t>& regions, int channels) {
  if (image.empty()) throw ParameterError("image", "is empty");
  if (count < 1 || count > 255) throw ParameterError("clusters", "must be in [1, 255], got " + std::to_string(count));
  if (channels == 0) channels = image.channels;
  if (channels < 1 || channels > image.channels)
    throw ParameterError("channels", "must be in [1, " + std::to_string(image.channels) + "]");
  const std::size_t pixels = image.pixelCount();
  if (!regions.empty() && regions.size() != pixels) throw ParameterError("regions", "must hold one label per pixel");
  // One cluster per region present, at the region's first pixel.
  Clustering k{&image, channels, {}, {}};
  for (std::uint8_t region : {std::uint8_t(0), std::uint8_t(1)})
    for (std::size_t p = 0; p < pixels; ++p)
      if (regionOf(regions, p) == region) {
        k.regions.push_back(region);
        k.centers.insert(k.centers.end(), image.pixels.begin() + std::ptrdiff_t(p * image.channels),
                         image.pixels.begin() + std::ptrdiff_t(p * image.channels + channels));
        break;
      }
  if (count < k.clusters())
    throw ParameterError("clusters", "two regions need at least two clusters, got " + std::to_string(count));
  std::vector<std::uint8_t> labels = lloyd(k, regions);
  while (k.clusters() < count) {
    // The region with the largest mean error gets the next cluster, split off its worst cluster at
    // that cluster's farthest pixel.
    double regionError[2] = {0, 0}, regionCount[2] = {0, 0};
    std::vector<double> clusterError(std::size_t(k.clusters()), 0.0);
    std::vector<float> farthest(std::size_t(k.clusters()), -1.0f);
    std::vector<std::size_t> farthestPixel(std::size_t(k.clusters()), 0);
    for (std::size_t p = 0; p < pixels; ++p) {
      const float d = k.distance(p, labels[p]);
      const std::uint8_t r = regionOf(regions, p);
      regionError[r] += d, regionCount[r] += 1, clusterError[labels[p]] += d;
      if (d > farthest[labels[p]]) farthest[labels[p]] = d, farthestPixel[labels[p]] = p;
    }
    int region = 0;
    if (regionCount[1] > 0 &&
        (regionCount[0] == 0 || regionError[1] / regionCount[1] > regionError[0] / regionCount[0]))
      region = 1;
    int worst = -1;
    for (int c = 0; c < k.clusters(); ++c)
      if (k.regions[std::size_t(c)] == region &&
          (worst < 0 || clusterError[std::size_t(c)] > clusterError[std::size_t(worst)]))
        worst = c;
    const std::size_t p = farthestPixel[std::size_t(worst)];
    k.regions.push_back(std::uint8_t(region));
    k.centers.insert(k.centers.end(), image.pixels.begin() + std::ptrdiff_t(p * image.channels),
                     image.pixels.begin() + std::ptrdiff_t(p * image.channels + channels));
    labels = lloyd(k, regions);
  }
  ColorClusters result;
  result.count = k.clusters();
  result.channels = channels;
  result.centers = std::move(k.centers);
  result.regions = std::move(k.regions);
  double error = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    const float* c = &result.centers[std::size_t(labels[p]) * channels];
    for (int i = 0; i < channels; ++i) {
      const double d = double(image.pixels[p * image.channels + i]) - c[i];
      error += d * d;
    }
  }
  result.meanSquaredError = error / double(pixels);
  result.labels = std::move(labels);
  return result;
}

}  // namespace texsynth
