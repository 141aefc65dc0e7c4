// Kept solid textures and the studio's texture settings.
#include "texsynth/studio/studio_solids.h"

#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth::studio {

TextureSettings TextureSettings::fromJson(const nlohmann::json& body, const TextureSettings& defaults) {
  TextureSettings settings = defaults;
  if (!body.is_object()) throw ParameterError("body", "give a JSON object");
  for (const auto& [key, value] : body.items()) {
    if (key == "method") {
      if (!value.is_string()) throw ParameterError("method", "give a string");
      settings.method = solidMethodName(parseSolidMethod(value.get<std::string>()));
    } else if (key == "exemplar") {
      if (!value.is_string()) throw ParameterError("exemplar", "give an exemplar id");
      settings.exemplarId = value.get<std::string>();
    } else if (key == "tiles") {
      if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < 0.1 ||
          value.get<double>() > 64)
        throw ParameterError("tiles", "give a number in [0.1, 64]");
      settings.tiles = value.get<float>();
    } else if (key == "seed") {
      if (!value.is_number_integer() || value.get<std::int64_t>() < 0)
        throw ParameterError("seed", "give a whole number >= 0");
      settings.seed = value.get<std::uint64_t>();
    } else {
      throw ParameterError(key, "unknown key (method, exemplar, tiles, seed)");
    }
  }
  return settings;
}

nlohmann::json TextureSettings::toJson() const {
  return {{"method", method}, {"exemplar", exemplarId}, {"tiles", tiles}, {"seed", seed}};
}

std::vector<Vec3f> KeptSolid::colors(const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals,
                                     Progress& progress) {
  if (!build_.texture->preparesOnDemand()) return build_.texture->evaluateColors(points, normals);
  // Another job's prepare may grow the caches this evaluation reads: both under the lock.
  std::lock_guard<std::mutex> lock(prepare_);
  build_.texture->prepare(points, progress);
  return build_.texture->evaluateColors(points, normals);
}

std::shared_ptr<KeptSolid> SolidShelf::find(const std::string& key) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = solids_.begin(); it != solids_.end(); ++it)
    if (it->key == key) {
      solids_.splice(solids_.begin(), solids_, it);
      return it->solid;
    }
  return nullptr;
}

void SolidShelf::keep(Kept kept) {
  std::lock_guard<std::mutex> lock(mutex_);
  solids_.remove_if([&](const Kept& entry) { return entry.key == kept.key; });
  solids_.push_front(std::move(kept));
  while (solids_.size() > keep_) solids_.pop_back();
}

void SolidShelf::forgetExemplar(const std::string& exemplarId) {
  std::list<Kept> dropped;  // destroyed after the lock: freeing a solid takes a moment
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = solids_.begin(); it != solids_.end();) {
      const auto next = std::next(it);
      if (it->exemplarId == exemplarId) dropped.splice(dropped.end(), solids_, it);
      it = next;
    }
  }
}

void SolidShelf::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  solids_.clear();
}

}  // namespace texsynth::studio
