// Disk cache of candidate triples, in the pattern of analysis_cache.cpp: a digest of the three
// images' pixels, the spacing, every option and the format version names the file; the
// header repeats version and key, and a checksum covers the payload. Anything that fails a
// check is recomputed, never trusted.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/byte_stream.h"
#include "texsynth/core/cache_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/hash.h"
#include "texsynth/exemplar/candidate_triples.h"

namespace texsynth {
namespace {

constexpr char kMagic[8] = {'T', 'S', 'X', 'T', 'R', 'I', 'P', 'L'};
constexpr std::int32_t kMaxSide = 1 << 16;  // sanity bound on stored sizes

void hashImage(Hasher& hasher, const Image& image) {
  hasher.value(image.width).value(image.height).value(image.channels).vector(image.pixels);
}

std::string serializePayload(const CandidateTriples& triples) {
  ByteWriter out;
  out.value(std::int32_t(triples.width));
  out.value(std::int32_t(triples.height));
  out.value(std::int32_t(triples.count));
  out.value(std::int32_t(triples.neighborhoodSize));
  for (int plane = 0; plane < 3; ++plane) {
    out.array(triples.triples[plane]);
    out.array(triples.errors[plane]);
  }
  return std::move(out.bytes);
}

// Every stored index in range, every error finite, non-negative and ascending per pixel.
bool validPlane(const CandidateTriples& t, int plane) {
  const std::size_t entries = std::size_t(t.pixelCount()) * t.count;
  if (t.triples[plane].size() != entries || t.errors[plane].size() != entries) return false;
  const std::int64_t pixels = t.pixelCount();
  for (std::size_t i = 0; i < entries; ++i) {
    const CoordinateTriple& c = t.triples[plane][i];
    if (c.xy < 0 || c.xy >= pixels || c.yz < 0 || c.yz >= pixels || c.zx < 0 || c.zx >= pixels) return false;
    const std::int32_t anchor = plane == 0 ? c.xy : plane == 1 ? c.yz : c.zx;
    if (anchor != std::int32_t(i / t.count)) return false;
    const float e = t.errors[plane][i];
    if (!std::isfinite(e) || e < 0.0f) return false;
    if (i % t.count != 0 && e < t.errors[plane][i - 1]) return false;
  }
  return true;
}

std::optional<CandidateTriples> parsePayload(std::string_view payload) {
  ByteReader in(payload);
  std::int32_t width = 0, height = 0, count = 0, n = 0;
  if (!in.value(width) || !in.value(height) || !in.value(count) || !in.value(n)) return std::nullopt;
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide || count < 1 || count > 4096 || n < 1 ||
      n % 2 == 0)
    return std::nullopt;
  CandidateTriples t;
  t.width = width;
  t.height = height;
  t.count = count;
  t.neighborhoodSize = n;
  for (int plane = 0; plane < 3; ++plane) {
    if (!in.array(t.triples[plane]) || !in.array(t.errors[plane])) return std::nullopt;
    if (!validPlane(t, plane)) return std::nullopt;
  }
  if (!in.atEnd()) return std::nullopt;
  return t;
}

}  // namespace

std::uint64_t candidateTriplesCacheKey(const Image& xy, const Image& yz, const Image& zx, int spacing,
                                       const CandidateTripleOptions& options) {
  Hasher hasher;
  hasher.string("candidate-triples").value(kCandidateTriplesFormatVersion);
  hashImage(hasher, xy);
  hashImage(hasher, yz);
  hashImage(hasher, zx);
  hasher.value(spacing).value(options.count).value(options.neighborhoodSize).value(options.searchWidth);
  hasher.value(options.refineTriples).value(options.consistencyFactor);
  return hasher.digest();
}

std::string candidateTriplesCachePath(const std::string& cacheDirectory, std::uint64_t key) {
  return detail::cacheFilePath(cacheDirectory, "triples", key, "tsxt");
}

std::string serializeCandidateTriples(const CandidateTriples& triples, std::uint64_t key) {
  return detail::sealCacheRecord(std::string_view(kMagic, sizeof kMagic), kCandidateTriplesFormatVersion, key,
                                 serializePayload(triples));
}

std::optional<CandidateTriples> deserializeCandidateTriples(std::string_view bytes, std::uint64_t expectedKey) {
  auto payload = detail::openCacheRecord(bytes, std::string_view(kMagic, sizeof kMagic), kCandidateTriplesFormatVersion,
                                         expectedKey);
  if (!payload) return std::nullopt;
  return parsePayload(*payload);
}

std::optional<CandidateTriples> loadCachedCandidateTriples(const std::string& path, std::uint64_t expectedKey) {
  std::optional<std::string> bytes = detail::readCacheFile(path);
  if (!bytes) return std::nullopt;
  return deserializeCandidateTriples(*bytes, expectedKey);
}

CandidateTriples computeCandidateTriplesCached(const Image& xy, const Image& yz, const Image& zx, int spacing,
                                               const CandidateTripleOptions& options, const std::string& cacheDirectory,
                                               Progress& progress) {
  validateCandidateTripleInputs(xy, yz, zx, spacing, options);
  const std::uint64_t key = candidateTriplesCacheKey(xy, yz, zx, spacing, options);
  const std::string path = candidateTriplesCachePath(cacheDirectory, key);
  progress.begin("candidate triples: reading cache", 1);
  std::optional<CandidateTriples> cached = loadCachedCandidateTriples(path, key);
  progress.advance();
  progress.end();
  if (cached && cached->width == xy.width && cached->height == xy.height && cached->count == options.count &&
      cached->neighborhoodSize == options.neighborhoodSize)
    return std::move(*cached);

  CandidateTriples triples = computeCandidateTriples(xy, yz, zx, spacing, options, progress);
  progress.begin("candidate triples: writing cache", 1);
  detail::writeCacheFile(cacheDirectory, path, serializeCandidateTriples(triples, key));
  progress.advance();
  progress.end();
  return triples;
}

}  // namespace texsynth
