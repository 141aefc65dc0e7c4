#include "texsynth/solid/solid_texture.h"

#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

// Fixed chunk size: the split of work never depends on the thread count.
constexpr std::int64_t kPointsPerChunk = 4096;

}  // namespace

SolidPlacement fitPlacement(const Box3f& bounds, int tileSize, float tiles) {
  if (!bounds.valid() || !bounds.min.allFinite() || !bounds.max.allFinite())
    throw ParameterError("bounds", "must be a finite, non-empty box");
  float longest = bounds.size().maxCoeff();
  if (!(longest > 0.0f)) throw ParameterError("bounds", "has zero extent");
  if (tileSize < 1) throw ParameterError("tileSize", "must be >= 1, got " + std::to_string(tileSize));
  if (!std::isfinite(tiles) || !(tiles > 0.0f)) throw ParameterError("tiles", "must be finite and > 0");
  return SolidPlacement{bounds.min, tiles * float(tileSize) / longest};
}

void validatePlacement(const SolidPlacement& placement) {
  if (!placement.origin.allFinite()) throw ParameterError("placement.origin", "must be finite");
  if (!std::isfinite(placement.pixelsPerUnit) || !(placement.pixelsPerUnit > 0.0f))
    throw ParameterError("placement.pixelsPerUnit", "must be finite and > 0");
}

void SolidTexture::evaluate(std::span<const Vec3f> points, std::span<const Vec3f> normals,
                            std::span<float> values) const {
  const std::size_t n = points.size();
  const std::size_t c = std::size_t(channels());
  if (!normals.empty() && normals.size() != n)
    throw ParameterError("normals", "must be empty or one per point (" + std::to_string(normals.size()) + " for " +
                                        std::to_string(n) + " points)");
  if (values.size() != n * c) throw ParameterError("values", "must hold channels() values per point");
  parallelForChunks(0, std::int64_t(n), kPointsPerChunk, [&](std::int64_t begin, std::int64_t end) {
    const std::size_t b = std::size_t(begin), count = std::size_t(end - begin);
    evaluateSerial(points.subspan(b, count), normals.empty() ? normals : normals.subspan(b, count),
                   values.subspan(b * c, count * c));
  });
}

std::vector<Vec3f> SolidTexture::evaluateColors(std::span<const Vec3f> points, std::span<const Vec3f> normals) const {
  const int c = channels();
  std::vector<float> values(points.size() * std::size_t(c));
  evaluate(points, normals, values);
  std::vector<Vec3f> colors(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float* v = &values[i * std::size_t(c)];
    colors[i] = c >= 3 ? Vec3f(v[0], v[1], v[2]) : Vec3f::Constant(v[0]);
  }
  return colors;
}

}  // namespace texsynth
