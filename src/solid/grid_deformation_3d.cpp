#include "texsynth/solid/grid_deformation_3d.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/gradient_noise.h"
#include "texsynth/core/random.h"
#include "texsynth/image/window_support.h"

namespace texsynth {

void validateGridDeformation(const GridDeformationOptions& options) {
  if (!options.cellSize.allFinite() || !(options.cellSize.minCoeff() > 0.0f))
    throw ParameterError("deformation.cellSize", "each component must be finite and > 0");
  if (!options.lambda.allFinite() || !(options.lambda.minCoeff() >= 0.0f))
    throw ParameterError("deformation.lambda", "each component must be finite and >= 0");
  requireDeformationClamp("deformation.clamp", options.clamp);
  if (!std::isfinite(options.noiseScale) || !(options.noiseScale > 0.0f))
    throw ParameterError("deformation.noiseScale", "must be finite and > 0");
}

GridDeformation3d::GridDeformation3d(const GridDeformationOptions& options) : options_(options) {
  validateGridDeformation(options);
  maxDisplacement_ = options.clamp * options.cellSize;
  for (int component = 0; component < 3; ++component) {
    componentSeed_[component] = hashKey(options.seed, std::uint64_t(component), 0, 1);
    for (int a = 0; a < 3; ++a)
      componentOffset_[component][a] =
          64.0f * uniform01(hashKey(options.seed, std::uint64_t(component), std::uint64_t(a), 2));
  }
}

Vec3f GridDeformation3d::cornerDisplacement(std::int64_t i, std::int64_t j, std::int64_t k) const {
  const float inv = 1.0f / options_.noiseScale;
  Vec3f d;
  for (int component = 0; component < 3; ++component) {
    if (options_.lambda[component] == 0.0f) {
      d[component] = 0.0f;
      continue;
    }
    const Vec3f& o = componentOffset_[component];
    const float n = gradientNoise3(float(i) * inv + o.x(), float(j) * inv + o.y(), float(k) * inv + o.z(),
                                   componentSeed_[component]);
    const float limit = maxDisplacement_[component];
    d[component] = std::clamp(n * options_.lambda[component] * options_.cellSize[component], -limit, limit);
  }
  return d;
}

Vec3f GridDeformation3d::map(const Vec3f& p, CellCache& cache) const {
  if (options_.lambda.maxCoeff() == 0.0f) return p;
  const Vec3f cellCoord = p.cwiseQuotient(options_.cellSize);
  const Vec3f base = cellCoord.array().floor();
  const Vec3f t = cellCoord - base;
  const std::int64_t i = std::int64_t(base.x()), j = std::int64_t(base.y()), k = std::int64_t(base.z());
  if (cache.cell[0] != i || cache.cell[1] != j || cache.cell[2] != k) {
    for (int corner = 0; corner < 8; ++corner)
      cache.corner[corner] = cornerDisplacement(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1));
    cache.cell[0] = i, cache.cell[1] = j, cache.cell[2] = k;
  }
  // The undisplaced corners interpolate back to p, so only the displacements are interpolated.
  Vec3f offset = Vec3f::Zero();
  for (int corner = 0; corner < 8; ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
    const float w = (dx ? t.x() : 1 - t.x()) * (dy ? t.y() : 1 - t.y()) * (dz ? t.z() : 1 - t.z());
    offset += w * cache.corner[corner];
  }
  return p + offset;
}

}  // namespace texsynth
