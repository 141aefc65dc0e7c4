#pragma once
// Internal: the nearest-neighbour backends behind computeSimilaritySets. Each finds, for
// query pixels, candidate pixels outside the query's exclusion window; the caller ranks them
// canonically, so backends only have to agree on *which* pixels are nearest.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>

#include "texsynth/exemplar/similarity_sets.h"

namespace texsynth::detail {

// The toroidal (2r+1)^2 square of pixels that may not be similar to its center.
struct ExclusionWindow {
  int width = 0, height = 0, radius = 0;

  bool excludes(std::int32_t center, std::int32_t candidate) const {
    return ringDistance(center % width, candidate % width, width) <= radius &&
           ringDistance(center / width, candidate / width, height) <= radius;
  }
  // Pixels inside one window (it may wrap onto itself on a small exemplar).
  std::int64_t pixelCount() const {
    std::int64_t side = 2LL * radius + 1;
    return std::min<std::int64_t>(side, width) * std::min<std::int64_t>(side, height);
  }

 private:
  static int ringDistance(int a, int b, int n) {
    int d = a > b ? a - b : b - a;
    return d < n - d ? d : n - d;
  }
};

// The canonical distance every ranking uses: float sum of squared differences in order.
inline float squaredDistance(const float* a, const float* b, int dimension) {
  float sum = 0.0f;
  for (int i = 0; i < dimension; ++i) {
    float d = a[i] - b[i];
    sum += d * d;
  }
  return sum;
}

class NeighborSearch {
 public:
  virtual ~NeighborSearch() = default;
  // For each query pixel, writes `wanted` candidate pixels outside its window to
  // out[q*wanted ...], nearest first by the backend's own measure; -1 where it found fewer.
  virtual void search(std::span<const std::int32_t> queries, int wanted, std::int32_t* out) = 0;
};

// Builds the index for `vectors` (which must outlive it) for the chosen backend.
std::unique_ptr<NeighborSearch> makeNeighborSearch(const PixelVectors& vectors, const ExclusionWindow& window,
                                                   const SimilarityOptions& options);

std::unique_ptr<NeighborSearch> makeBruteForceSearch(const PixelVectors& vectors, const ExclusionWindow& window);
std::unique_ptr<NeighborSearch> makeNanoflannSearch(const PixelVectors& vectors, const ExclusionWindow& window,
                                                    float epsilon);
std::unique_ptr<NeighborSearch> makeFaissSearch(const PixelVectors& vectors, const ExclusionWindow& window,
                                                const SimilarityOptions& options);

}  // namespace texsynth::detail
