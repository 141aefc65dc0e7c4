#pragma once
// The studio's solid textures, built through the library's factory (solid_factory.h, as the
// command line) and kept for reuse: a preview, a cut and an export with the same settings share
// one solid, so a lazy solid's synthesized voxels serve them all. A lazy solid prepares on one
// thread at a time, and evaluates under the same lock (each kept solid has its own); the other methods
// evaluate from any thread.
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "texsynth/core/progress.h"
#include "texsynth/solid/solid_factory.h"

namespace texsynth::studio {

// What the user chose to texture with.
struct TextureSettings {
  std::string method = "tile-deform";  // tile-deform | tile-blend | lazy
  std::string exemplarId;
  float tiles = 2.0f;  // exemplar tiles across the mesh's longest side
  std::uint64_t seed = 1;

  // Reads {"method", "exemplar", "tiles", "seed"} over `defaults`; ParameterError for bad values.
  static TextureSettings fromJson(const nlohmann::json& body, const TextureSettings& defaults);
  nlohmann::json toJson() const;
};

class KeptSolid {
 public:
  explicit KeptSolid(SolidBuild build) : build_(std::move(build)) {}
  // Colours at the points (with normals, or none), synthesizing on demand first.
  std::vector<Vec3f> colors(const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals, Progress& progress);
  // consume(const SolidTexture&) after preparing exactly what it reads (withPrepared), under the lock.
  template <typename Consume>
  auto consume(Progress& progress, Consume consume) {
    std::lock_guard<std::mutex> lock(prepare_);
    return withPrepared(*build_.texture, progress, consume);
  }

 private:
  SolidBuild build_;
  std::mutex prepare_;
};

class SolidShelf {
 public:
  // Keeps the `keep` most recently used solids.
  explicit SolidShelf(std::size_t keep = 4) : keep_(keep) {}
  // The solid for `key`, made from the exemplar `exemplarId` by `recipe()` (called without the
  // shelf's lock held) if not kept.
  template <typename MakeRecipe>
  std::shared_ptr<KeptSolid> get(const std::string& key, const std::string& exemplarId, MakeRecipe recipe,
                                 Progress& progress);
  // Drops the solids made from an exemplar the catalog forgot (a job still using one keeps it).
  void forgetExemplar(const std::string& exemplarId);
  void clear();

 private:
  struct Kept {
    std::string key, exemplarId;
    std::shared_ptr<KeptSolid> solid;
  };
  std::shared_ptr<KeptSolid> find(const std::string& key);
  void keep(Kept kept);
  const std::size_t keep_;
  std::mutex mutex_;
  std::list<Kept> solids_;  // most recent first
};

template <typename MakeRecipe>
std::shared_ptr<KeptSolid> SolidShelf::get(const std::string& key, const std::string& exemplarId, MakeRecipe recipe,
                                           Progress& progress) {
  if (auto found = find(key)) return found;
  auto solid = std::make_shared<KeptSolid>(buildSolid(recipe(), progress));
  keep({key, exemplarId, solid});
  return solid;
}

}  // namespace texsynth::studio
