// FAISS backends: exact IndexFlatL2 and approximate IndexHNSWFlat. FAISS cannot skip the
// exclusion window during a search, so each query asks for k-1 plus the window's pixel
// count, which always leaves at least k-1 pixels outside the window.
#include <faiss/IndexFlat.h>
#include <faiss/IndexHNSW.h>
#include <omp.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <vector>

#include "neighbor_search.h"

namespace texsynth::detail {
namespace {

// FAISS parallelizes with OpenMP, not TBB: mirror texsynth's thread cap for one call.
class OpenMpThreadScope {
 public:
  explicit OpenMpThreadScope(int threads) : previous_(omp_get_max_threads()) { omp_set_num_threads(threads); }
  ~OpenMpThreadScope() { omp_set_num_threads(previous_); }
  OpenMpThreadScope(const OpenMpThreadScope&) = delete;
  OpenMpThreadScope& operator=(const OpenMpThreadScope&) = delete;

 private:
  int previous_;
};

class FaissSearch : public NeighborSearch {
 public:
  FaissSearch(const PixelVectors& vectors, const ExclusionWindow& window, const SimilarityOptions& options)
      : vectors_(vectors), window_(window), efSearch_(options.hnswEfSearch) {
    if (options.backend == AnnBackend::FaissHnsw) {
      auto hnsw = std::make_unique<faiss::IndexHNSWFlat>(vectors.dimension, options.hnswNeighbors);
      hnsw->hnsw.efConstruction = options.hnswEfConstruction;
      hnsw_ = hnsw.get();
      index_ = std::move(hnsw);
      // Parallel HNSW insertion makes the graph depend on thread timing; build on one thread.
      OpenMpThreadScope single(1);
      index_->add(vectors.pixelCount(), vectors.data);
    } else {
      index_ = std::make_unique<faiss::IndexFlatL2>(vectors.dimension);
      index_->add(vectors.pixelCount(), vectors.data);
    }
  }

  void search(std::span<const std::int32_t> queries, int wanted, std::int32_t* out) override {
    const std::int64_t asked = std::min<std::int64_t>(wanted + window_.pixelCount(), vectors_.pixelCount());
    const std::size_t count = queries.size();
    std::vector<float> queryVectors(count * vectors_.dimension);
    for (std::size_t q = 0; q < count; ++q)
      std::copy_n(vectors_.at(queries[q]), vectors_.dimension, &queryVectors[q * vectors_.dimension]);
    std::vector<float> distances(count * asked);
    std::vector<faiss::Index::idx_t> labels(count * asked);
    {
      OpenMpThreadScope threads(tbb::this_task_arena::max_concurrency());
      if (hnsw_) hnsw_->hnsw.efSearch = std::max<int>(efSearch_, int(asked));
      index_->search(faiss::Index::idx_t(count), queryVectors.data(), asked, distances.data(), labels.data());
    }
    for (std::size_t q = 0; q < count; ++q) {
      std::int32_t* row = out + q * wanted;
      int filled = 0;
      for (std::int64_t i = 0; i < asked && filled < wanted; ++i) {
        faiss::Index::idx_t label = labels[q * asked + i];
        if (label < 0 || window_.excludes(queries[q], std::int32_t(label))) continue;
        row[filled++] = std::int32_t(label);
      }
      for (; filled < wanted; ++filled) row[filled] = -1;
    }
  }

 private:
  PixelVectors vectors_;
  ExclusionWindow window_;
  int efSearch_;
  std::unique_ptr<faiss::Index> index_;
  faiss::IndexHNSWFlat* hnsw_ = nullptr;
};

}  // namespace

std::unique_ptr<NeighborSearch> makeFaissSearch(const PixelVectors& vectors, const ExclusionWindow& window,
                                                const SimilarityOptions& options) {
  return std::make_unique<FaissSearch>(vectors, window, options);
}

}  // namespace texsynth::detail
