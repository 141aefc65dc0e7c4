#include "texsynth/solid/region_solid.h"

#include <cmath>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/geometry/surface_projector.h"

namespace texsynth {

RegionSolidTexture::RegionSolidTexture(std::vector<std::shared_ptr<SolidTexture>> parts, RegionRule rule)
    : parts_(std::move(parts)), rule_(std::move(rule)) {
  if (parts_.empty()) throw ParameterError("parts", "needs at least one solid texture");
  for (const auto& part : parts_) {
    if (!part) throw ParameterError("parts", "holds a null solid texture");
    if (part->channels() != parts_.front()->channels())
      throw ParameterError("parts", "have different channel counts (" + std::to_string(part->channels()) + " and " +
                                        std::to_string(parts_.front()->channels()) + ")");
  }
  if (!rule_) throw ParameterError("rule", "is empty");
}

int RegionSolidTexture::regionOf(const Vec3f& point) const {
  const int region = rule_(point);
  TS_CHECK_MSG(region >= 0 && region < int(parts_.size()), "region rule gave a region without a part");
  return region;
}

void RegionSolidTexture::prepare(std::span<const Vec3f> points, Progress& progress) {
  std::vector<std::vector<Vec3f>> buckets(parts_.size());
  for (const Vec3f& p : points) buckets[std::size_t(regionOf(p))].push_back(p);
  for (std::size_t i = 0; i < parts_.size(); ++i)
    if (!buckets[i].empty()) parts_[i]->prepare(buckets[i], progress);
}

bool RegionSolidTexture::preparesOnDemand() const {
  for (const auto& part : parts_)
    if (part->preparesOnDemand()) return true;
  return false;
}

void RegionSolidTexture::evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f> normals,
                                        std::span<float> values) const {
  const std::size_t c = std::size_t(channels());
  for (std::size_t i = 0; i < points.size(); ++i)
    parts_[std::size_t(regionOf(points[i]))]->evaluateSerial(
        points.subspan(i, 1), normals.empty() ? normals : normals.subspan(i, 1), values.subspan(i * c, c));
}

RegionSolidTexture::RegionRule surfaceShellRule(const Mesh& mesh, float depth) {
  if (!std::isfinite(depth) || !(depth > 0))
    throw ParameterError("depth", "must be a finite number > 0, got " + std::to_string(depth));
  auto projector = std::make_shared<const SurfaceProjector>(mesh);
  // Outside the (closed) mesh is the shell too, so the inner exemplar never shows there.
  return [projector, depth](const Vec3f& p) {
    return projector->closestPoint(p).distance <= depth || !projector->inside(p) ? 0 : 1;
  };
}

}  // namespace texsynth
