// Exact reference search: every pair, keeping the best `wanted` in a small sorted list.
#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "neighbor_search.h"
#include "texsynth/core/parallel.h"

namespace texsynth::detail {
namespace {

class BruteForceSearch : public NeighborSearch {
 public:
  BruteForceSearch(const PixelVectors& vectors, const ExclusionWindow& window) : vectors_(vectors), window_(window) {}

  void search(std::span<const std::int32_t> queries, int wanted, std::int32_t* out) override {
    parallelForChunks(0, std::int64_t(queries.size()), 16, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::pair<float, std::int32_t>> best;
      for (std::int64_t q = begin; q < end; ++q) {
        searchOne(queries[q], wanted, best);
        std::int32_t* row = out + q * wanted;
        for (int i = 0; i < wanted; ++i) row[i] = i < int(best.size()) ? best[i].second : -1;
      }
    });
  }

 private:
  void searchOne(std::int32_t query, int wanted, std::vector<std::pair<float, std::int32_t>>& best) const {
    best.clear();
    const float* target = vectors_.at(query);
    const std::int64_t pixels = vectors_.pixelCount();
    float worst = std::numeric_limits<float>::infinity();
    for (std::int64_t pixel = 0; pixel < pixels; ++pixel) {
      float d = squaredDistance(target, vectors_.at(pixel), vectors_.dimension);
      if (d >= worst && int(best.size()) == wanted) continue;
      if (window_.excludes(query, std::int32_t(pixel))) continue;
      // Insertion into a sorted list of at most `wanted` entries (wanted is small).
      std::pair<float, std::int32_t> entry{d, std::int32_t(pixel)};
      auto position = std::upper_bound(best.begin(), best.end(), entry);
      best.insert(position, entry);
      if (int(best.size()) > wanted) best.pop_back();
      if (int(best.size()) == wanted) worst = best.back().first;
    }
  }

  PixelVectors vectors_;
  ExclusionWindow window_;
};

}  // namespace

std::unique_ptr<NeighborSearch> makeBruteForceSearch(const PixelVectors& vectors, const ExclusionWindow& window) {
  return std::make_unique<BruteForceSearch>(vectors, window);
}

}  // namespace texsynth::detail
