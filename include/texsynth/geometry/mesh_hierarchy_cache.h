#pragma once
// Disk cache of mesh hierarchies (retiling a 48k-vertex hierarchy takes seconds). A file is
// keyed by a digest of the input's positions and triangles, the options, the retiling settings,
// the CGAL version and the format version; on load the envelope (magic, version, key, size,
// checksum: core/cache_file.h) and the hierarchy's structure are verified, and anything that
// does not match is rebuilt, never trusted. Files are written atomically.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "texsynth/geometry/mesh_hierarchy.h"

namespace texsynth {

// Bump whenever the hierarchy (retiling, parents) or the file layout changes.
inline constexpr std::uint32_t kMeshHierarchyCacheFormatVersion = 2;

// Digest of (format version, CGAL version, retiling settings, input positions and triangles,
// every field of `options`).
std::uint64_t meshHierarchyCacheKey(const Mesh& input, const MeshHierarchyOptions& options);

// "<cacheDirectory>/hierarchy-<16 hex digits>.tsxm".
std::string meshHierarchyCachePath(const std::string& cacheDirectory, std::uint64_t key);

// The file image of a hierarchy (envelope + payload). `seconds` is not stored.
std::string serializeMeshHierarchy(const MeshHierarchy& hierarchy, std::uint64_t key);

// Parses serializeMeshHierarchy's bytes; nullopt if they are truncated, corrupted, of another
// format version, stored under another key, or describe an inconsistent hierarchy (an index out
// of range, a count that does not match).
std::optional<MeshHierarchy> deserializeMeshHierarchy(std::string_view bytes, std::uint64_t expectedKey);

// Reads a cache file; nullopt if it is missing or fails any check of deserializeMeshHierarchy.
std::optional<MeshHierarchy> loadCachedMeshHierarchy(const std::string& path, std::uint64_t expectedKey);

// buildMeshHierarchy through the cache in `cacheDirectory` (the CLI passes the directory the
// exemplar-analysis cache uses): the cached hierarchy when a valid file exists, otherwise a fresh
// build, (re)written atomically. Creates cacheDirectory if needed; throws OutputError if it
// cannot be created or written, and what buildMeshHierarchy throws.
MeshHierarchy buildMeshHierarchyCached(const Mesh& input, const MeshHierarchyOptions& options,
                                       const std::string& source, const std::string& cacheDirectory,
                                       Progress& progress = noProgress());

}  // namespace texsynth
