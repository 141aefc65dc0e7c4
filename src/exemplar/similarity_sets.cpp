#include "texsynth/exemplar/similarity_sets.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include "neighbor_search.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

using detail::ExclusionWindow;

// Queries per search call: the unit of progress reports and of cancellation.
constexpr std::size_t kQueriesPerStep = 4096;

void validate(const PixelVectors& vectors, const SimilarityOptions& options, const ExclusionWindow& window) {
  TS_CHECK(vectors.data != nullptr && vectors.width > 0 && vectors.height > 0 && vectors.dimension > 0);
  if (options.count < 1)
    throw ParameterError("similarCount", "must be at least 1, got " + std::to_string(options.count));
  if (options.exclusionRadius < 0)
    throw ParameterError("exclusionRadius", "must be >= 0, got " + std::to_string(options.exclusionRadius));
  if (vectors.pixelCount() - window.pixelCount() < options.count - 1)
    throw ParameterError("similarCount", "a " + std::to_string(vectors.width) + "x" + std::to_string(vectors.height) +
                                             " exemplar has too few pixels outside the exclusion radius " +
                                             std::to_string(options.exclusionRadius) + " for " +
                                             std::to_string(options.count) + " similar pixels");
  if (!(options.nanoflannEpsilon >= 0.0f))
    throw ParameterError("nanoflannEpsilon", "must be >= 0, got " + std::to_string(options.nanoflannEpsilon));
  if (options.hnswNeighbors < 2 || options.hnswEfConstruction < 1 || options.hnswEfSearch < 1)
    throw ParameterError("hnsw", "graph degree must be >= 2 and beam widths >= 1");
}

// Orders one query's candidates canonically and writes its similarity set.
// Returns false if the backend found fewer than count-1 candidates.
bool finishRow(const PixelVectors& vectors, std::int32_t query, const std::int32_t* candidates, int wanted,
               std::vector<std::pair<float, std::int32_t>>& ranked, std::int32_t* row) {
  ranked.clear();
  for (int i = 0; i < wanted; ++i) {
    if (candidates[i] < 0) return false;
    ranked.emplace_back(detail::squaredDistance(vectors.at(query), vectors.at(candidates[i]), vectors.dimension),
                        candidates[i]);
  }
  std::sort(ranked.begin(), ranked.end());
  row[0] = query;
  for (int i = 0; i < wanted; ++i) row[i + 1] = ranked[i].second;
  return true;
}

}  // namespace

std::string annBackendName(AnnBackend backend) {
  switch (backend) {
    case AnnBackend::Nanoflann:
      return "nanoflann";
    case AnnBackend::FaissFlat:
      return "faiss-flat";
    case AnnBackend::FaissHnsw:
      return "faiss-hnsw";
    case AnnBackend::BruteForce:
      return "brute-force";
  }
  throw ParameterError("annBackend", "unknown backend value " + std::to_string(int(backend)));
}

AnnBackend parseAnnBackend(const std::string& name) {
  for (AnnBackend b : {AnnBackend::Nanoflann, AnnBackend::FaissFlat, AnnBackend::FaissHnsw, AnnBackend::BruteForce})
    if (annBackendName(b) == name) return b;
  throw ParameterError("annBackend",
                       "unknown backend '" + name + "' (expected nanoflann, faiss-flat, faiss-hnsw or brute-force)");
}

namespace detail {
std::unique_ptr<NeighborSearch> makeNeighborSearch(const PixelVectors& vectors, const ExclusionWindow& window,
                                                   const SimilarityOptions& options) {
  switch (options.backend) {
    case AnnBackend::Nanoflann:
      return makeNanoflannSearch(vectors, window, options.nanoflannEpsilon);
    case AnnBackend::FaissFlat:
    case AnnBackend::FaissHnsw:
      return makeFaissSearch(vectors, window, options);
    case AnnBackend::BruteForce:
      return makeBruteForceSearch(vectors, window);
  }
  throw ParameterError("annBackend", "unknown backend value " + std::to_string(int(options.backend)));
}
}  // namespace detail

std::vector<std::int32_t> computeSimilaritySets(const PixelVectors& vectors, std::span<const std::int32_t> queries,
                                                const SimilarityOptions& options, Progress& progress) {
  const ExclusionWindow window{vectors.width, vectors.height, options.exclusionRadius};
  validate(vectors, options, window);
  for (std::int32_t q : queries)
    if (q < 0 || q >= vectors.pixelCount()) throw ParameterError("queries", "pixel index out of range");
  const int count = options.count;
  std::vector<std::int32_t> sets(queries.size() * count);
  if (count == 1) {
    std::copy(queries.begin(), queries.end(), sets.begin());
    progress.advance(std::int64_t(queries.size()));
    return sets;
  }
  const int wanted = count - 1;
  auto search = detail::makeNeighborSearch(vectors, window, options);
  std::vector<std::int32_t> candidates;
  std::vector<std::int32_t> shortRows;  // queries the backend could not fill (approximate search)
  for (std::size_t first = 0; first < queries.size(); first += kQueriesPerStep) {
    const std::size_t stepCount = std::min(kQueriesPerStep, queries.size() - first);
    auto stepQueries = queries.subspan(first, stepCount);
    candidates.resize(stepCount * wanted);
    search->search(stepQueries, wanted, candidates.data());
    std::vector<char> complete(stepCount);
    parallelForChunks(0, std::int64_t(stepCount), 256, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::pair<float, std::int32_t>> ranked;
      for (std::int64_t q = begin; q < end; ++q)
        complete[q] =
            finishRow(vectors, stepQueries[q], &candidates[q * wanted], wanted, ranked, &sets[(first + q) * count]);
    });
    for (std::size_t q = 0; q < stepCount; ++q)
      if (!complete[q]) shortRows.push_back(std::int32_t(first + q));
    progress.advance(std::int64_t(stepCount));
  }
  if (!shortRows.empty()) {
    // Rare: an approximate graph search returned too few pixels outside the window.
    std::vector<std::int32_t> shortQueries(shortRows.size());
    for (std::size_t i = 0; i < shortRows.size(); ++i) shortQueries[i] = queries[shortRows[i]];
    auto exact = detail::makeBruteForceSearch(vectors, window);
    candidates.resize(shortQueries.size() * wanted);
    exact->search(shortQueries, wanted, candidates.data());
    std::vector<std::pair<float, std::int32_t>> ranked;
    for (std::size_t i = 0; i < shortRows.size(); ++i) {
      bool filled = finishRow(vectors, shortQueries[i], &candidates[i * wanted], wanted, ranked,
                              &sets[std::size_t(shortRows[i]) * count]);
      TS_CHECK(filled);
    }
  }
  return sets;
}

std::vector<std::int32_t> computeSimilaritySets(const PixelVectors& vectors, const SimilarityOptions& options,
                                                Progress& progress) {
  std::vector<std::int32_t> all(std::size_t(vectors.pixelCount()));
  std::iota(all.begin(), all.end(), 0);
  return computeSimilaritySets(vectors, all, options, progress);
}

double similarityRecall(std::span<const std::int32_t> found, std::span<const std::int32_t> exact, int count) {
  TS_CHECK(count >= 1 && found.size() == exact.size() && found.size() % count == 0);
  if (count == 1 || found.empty()) return 1.0;
  std::size_t hits = 0, total = 0;
  for (std::size_t row = 0; row < found.size(); row += count)
    for (int i = 1; i < count; ++i) {
      ++total;
      auto begin = exact.begin() + row + 1, end = exact.begin() + row + count;
      hits += std::find(begin, end, found[row + i]) != end;
    }
  return double(hits) / double(total);
}

}  // namespace texsynth
