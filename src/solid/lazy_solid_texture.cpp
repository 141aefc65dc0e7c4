#include "texsynth/solid/lazy_solid_texture.h"

#include <cmath>
#include <limits>

#include "texsynth/core/error.h"

namespace texsynth {

LazySolidTexture::LazySolidTexture(std::shared_ptr<LazySolid> solid, const SolidPlacement& placement)
    : solid_(std::move(solid)), placement_(placement) {
  if (!solid_) throw ParameterError("solid", "is null");
  validatePlacement(placement_);
}

Vec3i LazySolidTexture::voxelOf(const Vec3f& point) const {
  const Vec3f e = placement_.toExemplar(point);
  return {int(std::floor(e.x())), int(std::floor(e.y())), int(std::floor(e.z()))};
}

namespace {
// The exemplar position of a point, checked against the coordinate range LazySolid accepts.
Vec3f checkedExemplarPosition(const SolidPlacement& placement, const Vec3f& point, const char* parameter) {
  const Vec3f e = placement.toExemplar(point);
  if (!e.allFinite() || e.cwiseAbs().maxCoeff() >= float(1 << 19))
    throw ParameterError(parameter, "must be finite and within 2^19 exemplar pixels of the placement origin");
  return e;
}
}  // namespace

void LazySolidTexture::prepare(std::span<const Vec3f> points, Progress& progress) {
  std::vector<Vec3i> voxels;
  voxels.reserve(points.size());
  for (const Vec3f& p : points) {
    checkedExemplarPosition(placement_, p, "points");
    voxels.push_back(voxelOf(p));
  }
  solid_->synthesize(voxels, progress);
}

void setLazyDomain(LazySolidOptions& options, const SolidPlacement& placement, const Box3f& box) {
  if (!box.valid()) throw ParameterError("box", "is empty");
  validatePlacement(placement);
  Vec3i lo = Vec3i::Constant(std::numeric_limits<int>::max()), hi = Vec3i::Constant(std::numeric_limits<int>::min());
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3f p((corner & 1 ? box.max : box.min).x(), (corner & 2 ? box.max : box.min).y(),
                  (corner & 4 ? box.max : box.min).z());
    const Vec3f e = checkedExemplarPosition(placement, p, "box");
    const Vec3i v(int(std::floor(e.x())), int(std::floor(e.y())), int(std::floor(e.z())));
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  options.domainMin = lo;
  options.domainSize = hi - lo + Vec3i::Ones();
}

void LazySolidTexture::evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f>,
                                      std::span<float> values) const {
  const std::size_t c = std::size_t(channels());
  for (std::size_t i = 0; i < points.size(); ++i) solid_->color(voxelOf(points[i]), values.data() + i * c);
}

}  // namespace texsynth
