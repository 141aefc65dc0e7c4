// Disk cache of a lazy solid's coarsest level (its whole torus), in the envelope the other
// caches share: the blocks' keys and triples in key order. Anything that fails a check (the
// envelope, the torus' block set, an index out of range) is a miss and is synthesized again.
#include <algorithm>

#include "texsynth/core/byte_stream.h"
#include "texsynth/core/cache_file.h"
#include "texsynth/solid/lazy_blocks.h"

namespace texsynth::lazy {
namespace {
constexpr char kMagic[8] = {'T', 'S', 'X', 'C', 'O', 'A', 'R', 'S'};
}  // namespace

std::string coarsestCachePath(const std::string& cacheDirectory, std::uint64_t key) {
  return detail::cacheFilePath(cacheDirectory, "coarsest", key, "tsxc");
}

std::string serializeCoarsestLevel(const BlockCache& cache, std::uint64_t key) {
  std::vector<BlockKey> keys;
  for (const auto& entry : cache) keys.push_back(entry.first);
  std::sort(keys.begin(), keys.end());
  std::vector<CoordinateTriple> triples;
  triples.reserve(keys.size() * kBlockVoxels);
  for (BlockKey k : keys) {
    const TripleBlock& block = cache.at(k).triples;
    triples.insert(triples.end(), block.begin(), block.end());
  }
  ByteWriter out;
  out.array(keys);
  out.array(triples);
  return detail::sealCacheRecord(std::string_view(kMagic, sizeof kMagic), kCoarsestCacheFormatVersion, key, out.bytes);
}

std::optional<BlockCache> loadCoarsestLevel(const std::string& path, std::uint64_t key, const Vec3i& torusMin,
                                            const Vec3i& torusSize, std::int32_t pixelCount) {
  const std::optional<std::string> bytes = detail::readCacheFile(path);
  if (!bytes) return std::nullopt;
  const auto payload =
      detail::openCacheRecord(*bytes, std::string_view(kMagic, sizeof kMagic), kCoarsestCacheFormatVersion, key);
  if (!payload) return std::nullopt;
  ByteReader in(*payload);
  std::vector<BlockKey> keys;
  std::vector<CoordinateTriple> triples;
  if (!in.array(keys) || !in.array(triples) || !in.atEnd()) return std::nullopt;
  if (keys != torusBlocks(torusMin, torusSize) || triples.size() != keys.size() * kBlockVoxels) return std::nullopt;
  const auto inRange = [&](std::int32_t i) { return i >= 0 && i < pixelCount; };
  if (!std::all_of(triples.begin(), triples.end(),
                   [&](const CoordinateTriple& t) { return inRange(t.xy) && inRange(t.yz) && inRange(t.zx); }))
    return std::nullopt;
  BlockCache cache;
  cache.reserve(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
    std::copy_n(triples.begin() + std::ptrdiff_t(i * kBlockVoxels), kBlockVoxels, cache[keys[i]].triples.begin());
  return cache;
}

}  // namespace texsynth::lazy
