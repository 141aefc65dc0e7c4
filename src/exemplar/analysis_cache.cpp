#include "texsynth/exemplar/analysis_cache.h"

#include <cstdio>
#include <filesystem>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/byte_stream.h"
#include "texsynth/core/cache_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/hash.h"

namespace texsynth {
namespace {

constexpr char kMagic[8] = {'T', 'S', 'X', 'A', 'N', 'A', 'L', 'Y'};
// Sanity bound on stored sizes, far above any real exemplar; rejects absurd headers early.
constexpr std::uint32_t kMaxSide = 1 << 16;

void hashImage(Hasher& hasher, const Image& image) {
  hasher.value(image.width).value(image.height).value(image.channels).vector(image.pixels);
}

void writeLevel(ByteWriter& out, const ExemplarLevel& level) {
  out.value(std::int32_t(level.spacing));
  out.value(std::int32_t(level.neighborhoodSize));
  out.value(std::int32_t(level.image.channels));
  out.array(level.image.pixels);
  const PcaBasis& pca = level.pca;
  out.value(std::int32_t(pca.inputDimension));
  out.value(std::int32_t(pca.outputDimension));
  out.value(pca.totalVariance);
  out.value(pca.keptEnergy);
  out.array(pca.mean);
  out.array(pca.basis);
  out.array(pca.variances);
  out.array(level.projected);
  out.array(level.similar);
}

// Reads one level and checks it against the analysis it belongs to.
bool readLevel(ByteReader& in, const ExemplarAnalysis& analysis, ExemplarLevel& level) {
  std::int32_t spacing = 0, neighborhoodSize = 0, channels = 0, inputDimension = 0, outputDimension = 0;
  PcaBasis& pca = level.pca;
  if (!in.value(spacing) || !in.value(neighborhoodSize) || !in.value(channels)) return false;
  if (channels != analysis.channels() || spacing < 1) return false;
  if (neighborhoodSize < 1 || neighborhoodSize > kMaxNeighborhoodSize) return false;
  level.spacing = spacing;
  level.neighborhoodSize = neighborhoodSize;
  level.image.width = analysis.width;
  level.image.height = analysis.height;
  level.image.channels = channels;
  const std::size_t pixels = std::size_t(analysis.width) * analysis.height;
  if (!in.array(level.image.pixels) || level.image.pixels.size() != pixels * channels) return false;
  if (!in.value(inputDimension) || !in.value(outputDimension) || !in.value(pca.totalVariance) ||
      !in.value(pca.keptEnergy))
    return false;
  const int n = level.neighborhoodSize;
  if (inputDimension != n * n * channels || outputDimension < 1 || outputDimension > inputDimension) return false;
  pca.inputDimension = inputDimension;
  pca.outputDimension = outputDimension;
  if (!in.array(pca.mean) || !in.array(pca.basis) || !in.array(pca.variances)) return false;
  if (pca.mean.size() != std::size_t(inputDimension) ||
      pca.basis.size() != std::size_t(inputDimension) * outputDimension ||
      pca.variances.size() != std::size_t(outputDimension))
    return false;
  if (!in.array(level.projected) || level.projected.size() != pixels * outputDimension) return false;
  if (!in.array(level.similar) || level.similar.size() != pixels * analysis.similarCount) return false;
  for (std::int32_t pixel : level.similar)
    if (pixel < 0 || std::size_t(pixel) >= pixels) return false;
  return true;
}

std::string serializePayload(const ExemplarAnalysis& analysis) {
  ByteWriter out;
  out.value(std::int32_t(analysis.width));
  out.value(std::int32_t(analysis.height));
  out.value(std::int32_t(analysis.colorChannels));
  out.value(std::int32_t(analysis.hasFeatureChannel ? 1 : 0));
  out.value(std::int32_t(analysis.neighborhoodSize));
  out.value(std::int32_t(analysis.similarCount));
  out.value(std::int32_t(analysis.exclusionRadius));
  out.value(std::int32_t(analysis.levelCount()));
  for (const ExemplarLevel& level : analysis.levels) writeLevel(out, level);
  return std::move(out.bytes);
}

std::optional<ExemplarAnalysis> parsePayload(std::string_view payload) {
  ByteReader in(payload);
  std::int32_t width, height, colorChannels, hasFeature, neighborhoodSize, similarCount, exclusionRadius, levelCount;
  if (!in.value(width) || !in.value(height) || !in.value(colorChannels) || !in.value(hasFeature) ||
      !in.value(neighborhoodSize) || !in.value(similarCount) || !in.value(exclusionRadius) || !in.value(levelCount))
    return std::nullopt;
  if (width < 1 || height < 1 || std::uint32_t(width) > kMaxSide || std::uint32_t(height) > kMaxSide ||
      colorChannels < 1 || colorChannels > 64 || (hasFeature != 0 && hasFeature != 1) || neighborhoodSize < 1 ||
      neighborhoodSize > kMaxNeighborhoodSize || similarCount < 1 || exclusionRadius < 0 || levelCount < 1 ||
      levelCount > 32)
    return std::nullopt;
  ExemplarAnalysis analysis;
  analysis.width = width;
  analysis.height = height;
  analysis.colorChannels = colorChannels;
  analysis.hasFeatureChannel = hasFeature == 1;
  analysis.neighborhoodSize = neighborhoodSize;
  analysis.similarCount = similarCount;
  analysis.exclusionRadius = exclusionRadius;
  analysis.levels.resize(levelCount);
  for (ExemplarLevel& level : analysis.levels)
    if (!readLevel(in, analysis, level)) return std::nullopt;
  if (!in.atEnd()) return std::nullopt;
  return analysis;
}

}  // namespace

std::uint64_t analysisCacheKey(const Image& exemplar, const AnalysisOptions& options) {
  Hasher hasher;
  hasher.value(kAnalysisCacheFormatVersion);
  hashImage(hasher, exemplar);
  hasher.value(options.levelCount).value(options.neighborhoodSize).value(options.pcaDimensions);
  hasher.value(options.similarCount).value(options.exclusionRadius);
  hasher.value(options.levelNeighborhoodSizes.size());
  for (int n : options.levelNeighborhoodSizes) hasher.value(n);
  const SimilarityOptions& search = options.search;
  hasher.value(search.backend).value(search.nanoflannEpsilon);
  hasher.value(search.hnswNeighbors).value(search.hnswEfConstruction).value(search.hnswEfSearch);
  // search.count and search.exclusionRadius are overridden by the fields above.
  hashImage(hasher, options.featureMask);
  hasher.value(options.featureWeight);
  return hasher.digest();
}

std::string analysisCachePath(const std::string& cacheDirectory, std::uint64_t key) {
  return detail::cacheFilePath(cacheDirectory, "exemplar", key, "tsxa");
}

std::string serializeAnalysis(const ExemplarAnalysis& analysis, std::uint64_t key) {
  return detail::sealCacheRecord(std::string_view(kMagic, sizeof kMagic), kAnalysisCacheFormatVersion, key,
                                 serializePayload(analysis));
}

std::optional<ExemplarAnalysis> deserializeAnalysis(std::string_view bytes, std::uint64_t expectedKey) {
  auto payload =
      detail::openCacheRecord(bytes, std::string_view(kMagic, sizeof kMagic), kAnalysisCacheFormatVersion, expectedKey);
  if (!payload) return std::nullopt;
  return parsePayload(*payload);
}

std::optional<ExemplarAnalysis> loadCachedAnalysis(const std::string& path, std::uint64_t expectedKey) {
  std::optional<std::string> bytes = detail::readCacheFile(path);
  if (!bytes) return std::nullopt;
  return deserializeAnalysis(*bytes, expectedKey);
}

ExemplarAnalysis analyzeExemplarCached(const Image& exemplar, const AnalysisOptions& options,
                                       const std::string& cacheDirectory, Progress& progress) {
  validateAnalysisOptions(exemplar, options);
  const std::uint64_t key = analysisCacheKey(exemplar, options);
  const std::string path = analysisCachePath(cacheDirectory, key);
  progress.begin("exemplar: reading cache", 1);
  std::optional<ExemplarAnalysis> cached = loadCachedAnalysis(path, key);
  progress.advance();
  progress.end();
  if (cached) return std::move(*cached);

  ExemplarAnalysis analysis = analyzeExemplar(exemplar, options, progress);
  progress.begin("exemplar: writing cache", 1);
  detail::writeCacheFile(cacheDirectory, path, serializeAnalysis(analysis, key));
  progress.advance();
  progress.end();
  return analysis;
}

}  // namespace texsynth
