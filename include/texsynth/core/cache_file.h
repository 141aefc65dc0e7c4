#pragma once
// The on-disk envelope shared by the disk caches (exemplar analyses, candidate triples, mesh
// hierarchies): an 8-byte magic, format version, key, payload size and checksum, then the
// payload. Anything that does not match is treated as a miss and recomputed, never trusted.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace texsynth::detail {

// "<directory>/<prefix>-<key as 16 hex digits>.<extension>"
std::string cacheFilePath(const std::string& directory, const char* prefix, std::uint64_t key, const char* extension);

std::string sealCacheRecord(std::string_view magic, std::uint32_t version, std::uint64_t key, std::string_view payload);

// The payload when magic, version, key, size and checksum all match.
std::optional<std::string_view> openCacheRecord(std::string_view bytes, std::string_view magic, std::uint32_t version,
                                                std::uint64_t key);

// A cache file's bytes; nothing when it is missing or unreadable.
std::optional<std::string> readCacheFile(const std::string& path);

// Creates `directory` if needed (OutputError naming it otherwise) and writes `path` atomically.
void writeCacheFile(const std::string& directory, const std::string& path, const std::string& bytes);

}  // namespace texsynth::detail
