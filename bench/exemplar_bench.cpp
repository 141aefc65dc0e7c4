// Exemplar analysis kernels: neighborhood gathering, PCA projection, the k-coherence
// nearest-neighbour backends (time and recall against exact brute force) and the full
// analysis, on real GIMP exemplars at 128^2 (Stone/pink_marble.pat) and 256^2
// (Stone/stone33.pat, 156^2, resampled bilinearly to 256^2: no 256^2 pattern ships with
// gimp-data). Falls back to a generated pattern if gimp-data is missing.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "texsynth/core/data_paths.h"
#include "texsynth/core/random.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/exemplar/candidate_triples.h"
#include "texsynth/exemplar/gaussian_stack.h"
#include "texsynth/io/image_io.h"

using namespace texsynth;

namespace {

Image resampleWrapped(const Image& source, int size) {
  Image out(size, size, source.channels);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      source.sampleBilinearWrapped((x + 0.5f) * source.width / size, (y + 0.5f) * source.height / size,
                                   out.pixel(x, y));
  return out;
}

Image syntheticExemplar(int size) {
  Image image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = uniform01(hashKey(c, latticeId(x / 2, y / 2)));
  return image;
}

// The real exemplar used at this size (128 or 256).
const Image& exemplar(int size) {
  static std::map<int, Image> cache;
  auto found = cache.find(size);
  if (found != cache.end()) return found->second;
  auto path = gimpPattern(size == 128 ? "Stone/pink_marble.pat" : "Stone/stone33.pat");
  Image image = path ? readImage(*path).withChannels(3) : syntheticExemplar(size);
  if (image.width != size) image = resampleWrapped(image, size);
  return cache.emplace(size, std::move(image)).first->second;
}

// Finest-level PCA vectors (N = 5, D = 20), as the analysis computes them.
struct FinestLevel {
  Image image;
  PcaBasis pca;
  std::vector<float> projected;
  PixelVectors view() const { return {projected.data(), image.width, image.height, pca.outputDimension}; }
};

const FinestLevel& finestLevel(int size) {
  static std::map<int, std::unique_ptr<FinestLevel>> cache;
  auto& slot = cache[size];
  if (!slot) {
    slot = std::make_unique<FinestLevel>();
    slot->image = exemplar(size);
    NeighborhoodShape shape{5, 1, 3};
    slot->pca = fitNeighborhoodPca(slot->image, shape, 20);
    slot->projected = projectAllNeighborhoods(slot->image, shape, slot->pca);
  }
  return *slot;
}

// 1024 spread-out query pixels and their exact similarity sets (brute force), per (size, k).
constexpr int kRecallQueries = 1024;

std::vector<std::int32_t> sampleQueries(int size) {
  std::vector<std::int32_t> queries(kRecallQueries);
  const std::int64_t pixels = std::int64_t(size) * size;
  for (int i = 0; i < kRecallQueries; ++i)
    queries[i] = std::int32_t(uniformBelow(hashKey(99, i), std::uint32_t(pixels)));
  return queries;
}

SimilarityOptions searchOptions(AnnBackend backend, int k) {
  SimilarityOptions options;
  options.backend = backend;
  options.count = k;
  options.exclusionRadius = 2;
  return options;
}

const std::vector<std::int32_t>& exactSets(int size, int k) {
  static std::map<std::pair<int, int>, std::vector<std::int32_t>> cache;
  auto& slot = cache[{size, k}];
  if (slot.empty())
    slot =
        computeSimilaritySets(finestLevel(size).view(), sampleQueries(size), searchOptions(AnnBackend::BruteForce, k));
  return slot;
}

// Rows of a full run that belong to the sampled queries.
std::vector<std::int32_t> sampledRows(const std::vector<std::int32_t>& all, int size, int k) {
  std::vector<std::int32_t> rows;
  for (std::int32_t q : sampleQueries(size))
    rows.insert(rows.end(), all.begin() + std::size_t(q) * k, all.begin() + std::size_t(q + 1) * k);
  return rows;
}

void BM_GatherNeighborhood(benchmark::State& state) {
  const int n = int(state.range(0));
  const Image& image = exemplar(128);
  NeighborhoodShape shape{n, 4, 3};
  std::vector<float> out(shape.dimension());
  int pixel = 0;
  for (auto _ : state) {
    gatherNeighborhood(image, pixel % 128, (pixel / 128) % 128, shape, out.data());
    benchmark::DoNotOptimize(out.data());
    pixel += 37;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GatherNeighborhood)->Arg(5)->Arg(7)->Arg(9);

void BM_PcaProject(benchmark::State& state) {
  const int n = int(state.range(0));
  const Image& image = exemplar(128);
  NeighborhoodShape shape{n, 1, 3};
  PcaBasis pca = fitNeighborhoodPca(image, shape, 20);
  std::vector<float> neighborhood(shape.dimension()), out(pca.outputDimension);
  gatherNeighborhood(image, 17, 33, shape, neighborhood.data());
  for (auto _ : state) {
    pca.project(neighborhood.data(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["keptEnergy"] = pca.keptEnergy;
}
BENCHMARK(BM_PcaProject)->Arg(5)->Arg(7)->Arg(9);

// Full similarity sets of the finest level (index build + every pixel queried).
// Args: exemplar size, k, backend, backend knob (nanoflann eps x100, HNSW efSearch).
void BM_SimilaritySets(benchmark::State& state) {
  const int size = int(state.range(0)), k = int(state.range(1));
  SimilarityOptions options = searchOptions(AnnBackend(state.range(2)), k);
  if (options.backend == AnnBackend::Nanoflann) options.nanoflannEpsilon = float(state.range(3)) / 100.0f;
  if (options.backend == AnnBackend::FaissHnsw) options.hnswEfSearch = int(state.range(3));
  const FinestLevel& level = finestLevel(size);
  const std::vector<std::int32_t>& exact = exactSets(size, k);
  std::vector<std::int32_t> sets;
  for (auto _ : state) sets = computeSimilaritySets(level.view(), options);
  state.counters["recall"] = similarityRecall(sampledRows(sets, size, k), exact, k);
  state.counters["us_per_query"] =
      benchmark::Counter(double(state.iterations()) * size * size,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::OneK::kIs1000);
  state.SetLabel(annBackendName(options.backend));
}

// Exact brute-force backends are O(n^2): timed on the 1024 sampled queries only.
void BM_SimilaritySetsSampled(benchmark::State& state) {
  const int size = int(state.range(0)), k = int(state.range(1));
  SimilarityOptions options = searchOptions(AnnBackend(state.range(2)), k);
  const FinestLevel& level = finestLevel(size);
  const std::vector<std::int32_t> queries = sampleQueries(size);
  const std::vector<std::int32_t>& exact = exactSets(size, k);
  std::vector<std::int32_t> sets;
  for (auto _ : state) sets = computeSimilaritySets(level.view(), queries, options);
  state.counters["recall"] = similarityRecall(sets, exact, k);
  state.counters["us_per_query"] =
      benchmark::Counter(double(state.iterations()) * kRecallQueries,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::OneK::kIs1000);
  state.SetLabel(annBackendName(options.backend));
}

constexpr int kNanoflann = int(AnnBackend::Nanoflann), kFlat = int(AnnBackend::FaissFlat),
              kHnsw = int(AnnBackend::FaissHnsw), kBrute = int(AnnBackend::BruteForce);

void similarityArgs(benchmark::internal::Benchmark* b) {
  for (int size : {128, 256})
    for (int k : {2, 11}) {
      b->Args({size, k, kNanoflann, 0});
      b->Args({size, k, kNanoflann, 100});
      b->Args({size, k, kNanoflann, 200});
      b->Args({size, k, kHnsw, 16});
      b->Args({size, k, kHnsw, 64});
    }
}
BENCHMARK(BM_SimilaritySets)
    ->Apply(similarityArgs)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime();
BENCHMARK(BM_SimilaritySetsSampled)
    ->ArgsProduct({{128, 256}, {2, 11}, {kFlat, kBrute}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime();

void BM_AnalyzeExemplar(benchmark::State& state) {
  const Image& image = exemplar(int(state.range(0)));
  AnalysisOptions options;
  ExemplarAnalysis analysis;
  for (auto _ : state) analysis = analyzeExemplar(image, options);
  state.counters["levels"] = analysis.levelCount();
  state.counters["keptEnergy_finest"] = analysis.levels.back().pca.keptEnergy;
}
BENCHMARK(BM_AnalyzeExemplar)
    ->Arg(128)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime();

// Candidate triples of one stack level (paper defaults N_T = 12, N = 9; one exemplar serves
// all three planes). Args: exemplar size (64: top-left crop of the 128^2 exemplar), spacing.
void BM_CandidateTriples(benchmark::State& state) {
  const int size = int(state.range(0)), spacing = int(state.range(1));
  const Image image = size == 64 ? exemplar(128).crop(0, 0, 64, 64) : exemplar(size);
  CandidateTriples triples;
  for (auto _ : state) triples = computeCandidateTriples(image, image, image, spacing);
  double best = 0;
  for (std::int32_t p = 0; p < triples.pixelCount(); ++p) best += triples.errorsAt(Plane::XY, p)[0];
  state.counters["mean_best_error"] = best / double(triples.pixelCount());
}
BENCHMARK(BM_CandidateTriples)
    ->ArgsProduct({{64, 128}, {1, 2, 4, 8}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
