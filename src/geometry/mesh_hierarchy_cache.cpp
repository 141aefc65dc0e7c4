#include "texsynth/geometry/mesh_hierarchy_cache.h"

#include <CGAL/version.h>

#include <chrono>
#include <cmath>

#include "texsynth/core/byte_stream.h"
#include "texsynth/core/cache_file.h"
#include "texsynth/core/hash.h"
#include "texsynth/core/timing.h"
#include "texsynth/geometry/mesh_retiling.h"

namespace texsynth {
namespace {

constexpr std::string_view kMagic = "TSXMESHH";

bool validLevel(const MeshLevel& level, const MeshLevel* coarser) {
  const Mesh& mesh = level.mesh;
  const int vertices = int(mesh.positions.size());
  if (vertices == 0 || mesh.triangles.empty() || mesh.normals.size() != mesh.positions.size()) return false;
  if (!(level.spacing > 0) || !std::isfinite(level.spacing)) return false;
  for (const Vec3i& t : mesh.triangles)
    if ((t.array() < 0).any() || (t.array() >= vertices).any()) return false;
  if (!coarser) return level.parentTriangle.empty() && level.parentBarycentric.empty();
  if (level.parentTriangle.size() != mesh.positions.size() || level.parentBarycentric.size() != mesh.positions.size())
    return false;
  const int parents = int(coarser->mesh.triangles.size());
  for (int t : level.parentTriangle)
    if (t < 0 || t >= parents) return false;
  for (const Vec3f& w : level.parentBarycentric)
    if (!w.allFinite() || (w.array() < 0).any() || std::abs(w.sum() - 1) > 1e-3f) return false;
  return true;
}

}  // namespace

std::uint64_t meshHierarchyCacheKey(const Mesh& input, const MeshHierarchyOptions& options) {
  const RetileOptions retile;  // what buildMeshHierarchy retiles with
  Hasher hasher;
  hasher.value(kMeshHierarchyCacheFormatVersion).value(std::int64_t(CGAL_VERSION_NR));
  hasher.value(retile.iterations).value(retile.tolerance);
  hasher.vector(input.positions).vector(input.triangles);
  hasher.value(options.vertices).value(options.levels).value(options.ratio);
  return hasher.digest();
}

std::string meshHierarchyCachePath(const std::string& cacheDirectory, std::uint64_t key) {
  return detail::cacheFilePath(cacheDirectory, "hierarchy", key, "tsxm");
}

std::string serializeMeshHierarchy(const MeshHierarchy& hierarchy, std::uint64_t key) {
  ByteWriter out;
  out.value(std::uint64_t(hierarchy.levels.size()));
  for (const MeshLevel& level : hierarchy.levels) {
    out.array(level.mesh.positions);
    out.array(level.mesh.triangles);
    out.array(level.mesh.normals);
    out.value(level.spacing);
    out.array(level.parentTriangle);
    out.array(level.parentBarycentric);
  }
  return detail::sealCacheRecord(kMagic, kMeshHierarchyCacheFormatVersion, key, out.bytes);
}

std::optional<MeshHierarchy> deserializeMeshHierarchy(std::string_view bytes, std::uint64_t expectedKey) {
  const std::optional<std::string_view> payload =
      detail::openCacheRecord(bytes, kMagic, kMeshHierarchyCacheFormatVersion, expectedKey);
  if (!payload) return std::nullopt;
  ByteReader in(*payload);
  std::uint64_t levels = 0;
  if (!in.value(levels) || levels == 0 || levels > 64) return std::nullopt;
  MeshHierarchy hierarchy;
  hierarchy.levels.resize(std::size_t(levels));
  for (std::size_t l = 0; l < hierarchy.levels.size(); ++l) {
    MeshLevel& level = hierarchy.levels[l];
    if (!in.array(level.mesh.positions) || !in.array(level.mesh.triangles) || !in.array(level.mesh.normals) ||
        !in.value(level.spacing) || !in.array(level.parentTriangle) || !in.array(level.parentBarycentric))
      return std::nullopt;
    if (!validLevel(level, l > 0 ? &hierarchy.levels[l - 1] : nullptr)) return std::nullopt;
  }
  if (!in.atEnd()) return std::nullopt;
  return hierarchy;
}

std::optional<MeshHierarchy> loadCachedMeshHierarchy(const std::string& path, std::uint64_t expectedKey) {
  const std::optional<std::string> bytes = detail::readCacheFile(path);
  if (!bytes) return std::nullopt;
  return deserializeMeshHierarchy(*bytes, expectedKey);
}

MeshHierarchy buildMeshHierarchyCached(const Mesh& input, const MeshHierarchyOptions& options,
                                       const std::string& source, const std::string& cacheDirectory,
                                       Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  meshLevelVertexCounts(options);  // ParameterError before anything else
  const std::uint64_t key = meshHierarchyCacheKey(input, options);
  const std::string path = meshHierarchyCachePath(cacheDirectory, key);
  progress.begin("mesh hierarchy: reading cache", 1);
  std::optional<MeshHierarchy> cached = loadCachedMeshHierarchy(path, key);
  progress.advance();
  progress.end();
  if (cached && int(cached->levels.size()) == options.levels) {
    cached->seconds = secondsSince(start);
    return std::move(*cached);
  }

  MeshHierarchy hierarchy = buildMeshHierarchy(input, options, source, progress);
  progress.begin("mesh hierarchy: writing cache", 1);
  detail::writeCacheFile(cacheDirectory, path, serializeMeshHierarchy(hierarchy, key));
  progress.advance();
  progress.end();
  return hierarchy;
}

}  // namespace texsynth
