#pragma once
// k-coherence similarity sets (Tong et al. 2002; Lefebvre & Hoppe 2005): for each exemplar
// pixel u, C_1(u) = u itself followed by the k-1 exemplar pixels whose neighborhoods are
// most similar to u's (in PCA space), skipping any pixel within a toroidal radius of u so
// the set is not filled with u's own shifted copies. Built with a real nearest-neighbour
// library behind `AnnBackend`; bench/exemplar_bench.cpp measures the choices.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "texsynth/core/progress.h"

namespace texsynth {

enum class AnnBackend {
  Nanoflann,   // exact KD-tree (nanoflann); the exclusion window is applied inside the search
  FaissFlat,   // exact brute force (FAISS IndexFlatL2, BLAS)
  FaissHnsw,   // approximate graph search (FAISS IndexHNSWFlat)
  BruteForce,  // exact reference: every pair, no library
};

// "nanoflann", "faiss-flat", "faiss-hnsw", "brute-force".
std::string annBackendName(AnnBackend backend);
// Inverse of annBackendName; throws ParameterError for an unknown name.
AnnBackend parseAnnBackend(const std::string& name);

struct SimilarityOptions {
  // k: entries per pixel including the pixel itself (entry 0). L&H 2005 use k = 2; the
  // discrete optimization uses up to ~11.
  int count = 2;
  // Pixels v with toroidal |v.x-u.x| <= r and |v.y-u.y| <= r are never similar to u (a
  // (2r+1)^2 square). The analysis default is N/2, half the neighborhood size.
  int exclusionRadius = 2;
  // Chosen by bench/exemplar_bench.cpp (finest level, D = 20, real 128^2 and 256^2
  // exemplars, k = 2 and 11, 2 cores): at recall 1 exact nanoflann beat HNSW (ef 64) by
  // 1.4-2.4x; at recall >= 0.998 nanoflann with eps = 1 beat HNSW (ef 16) by 2-3.4x and
  // exact nanoflann by ~2x. Exact FAISS flat (reference BLAS) took 8-19x the CPU time per
  // query of exact nanoflann.
  AnnBackend backend = AnnBackend::Nanoflann;
  // Nanoflann: prune tree cells whose squared distance exceeds the current k-th best
  // divided by (1 + eps). 0 = exact search.
  float nanoflannEpsilon = 1.0f;
  // FAISS HNSW graph degree, build and search beam widths (FAISS defaults 32 / 40 / 16;
  // the search beam is raised to at least the number of neighbours asked for).
  int hnswNeighbors = 32;
  int hnswEfConstruction = 40;
  int hnswEfSearch = 64;
};

// Row-major per-pixel vectors of a width x height exemplar level (pixel index y*width+x).
struct PixelVectors {
  const float* data = nullptr;
  int width = 0, height = 0, dimension = 0;
  std::int64_t pixelCount() const { return std::int64_t(width) * height; }
  const float* at(std::int64_t pixel) const { return data + pixel * dimension; }
};

// Similarity sets of every pixel: pixelCount x options.count pixel indices; entry 0 is the
// pixel itself, then the others by increasing squared distance (ties: lower index first),
// where the distance is the float sum of squared differences in dimension order.
// Independent of thread count for every backend. Throws ParameterError for count < 1,
// radius < 0, or an exemplar too small to hold count-1 pixels outside the window.
// Advances `progress` by one unit per query (the caller begins and ends the stage).
std::vector<std::int32_t> computeSimilaritySets(const PixelVectors& vectors, const SimilarityOptions& options,
                                                Progress& progress = noProgress());

// The same for selected query pixels only: queries.size() x options.count indices.
std::vector<std::int32_t> computeSimilaritySets(const PixelVectors& vectors, std::span<const std::int32_t> queries,
                                                const SimilarityOptions& options, Progress& progress = noProgress());

// Fraction of the non-self entries of `found` that also appear in the same row of `exact`
// (both rows x count): the recall of an approximate search.
double similarityRecall(std::span<const std::int32_t> found, std::span<const std::int32_t> exact, int count);

}  // namespace texsynth
