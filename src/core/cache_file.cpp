#include "texsynth/core/cache_file.h"

#include <cstdio>
#include <filesystem>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/byte_stream.h"
#include "texsynth/core/error.h"
#include "texsynth/core/hash.h"

namespace texsynth::detail {

std::string cacheFilePath(const std::string& directory, const char* prefix, std::uint64_t key, const char* extension) {
  char name[64];
  std::snprintf(name, sizeof name, "%s-%016llx.%s", prefix, static_cast<unsigned long long>(key), extension);
  return (std::filesystem::path(directory) / name).string();
}

std::string sealCacheRecord(std::string_view magic, std::uint32_t version, std::uint64_t key,
                            std::string_view payload) {
  ByteWriter out;
  out.bytes.append(magic);
  out.value(version);
  out.value(key);
  out.value(std::uint64_t(payload.size()));
  out.value(Hasher().bytes(payload.data(), payload.size()).digest());
  out.bytes.append(payload);
  return std::move(out.bytes);
}

std::optional<std::string_view> openCacheRecord(std::string_view bytes, std::string_view magic, std::uint32_t version,
                                                std::uint64_t key) {
  ByteReader in(bytes);
  std::string_view readMagic, payload;
  std::uint32_t readVersion = 0;
  std::uint64_t readKey = 0, payloadSize = 0, checksum = 0;
  if (!in.raw(magic.size(), readMagic) || readMagic != magic) return std::nullopt;
  if (!in.value(readVersion) || readVersion != version) return std::nullopt;
  if (!in.value(readKey) || readKey != key) return std::nullopt;
  if (!in.value(payloadSize) || !in.value(checksum) || payloadSize != in.remaining()) return std::nullopt;
  if (!in.raw(payloadSize, payload)) return std::nullopt;
  if (Hasher().bytes(payload.data(), payload.size()).digest() != checksum) return std::nullopt;
  return payload;
}

std::optional<std::string> readCacheFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  try {
    return readFileBytes(path);
  } catch (const InputError&) {
    return std::nullopt;  // unreadable: treat like a missing entry and recompute
  }
}

void writeCacheFile(const std::string& directory, const std::string& path, const std::string& bytes) {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec) throw OutputError(directory, "cannot create the cache directory: " + ec.message());
  writeFileAtomically(path, bytes, Staging::Immediately);  // a cache outlives a failed run
}

}  // namespace texsynth::detail
