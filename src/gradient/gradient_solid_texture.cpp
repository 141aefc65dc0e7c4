#include "texsynth/gradient/gradient_solid_texture.h"

#include <algorithm>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

class GradientSolidTexture final : public SolidTexture {
 public:
  GradientSolidTexture(std::shared_ptr<const GradientSolid> solid, const GradientSolidTextureOptions& options)
      : solid_(std::move(solid)), placement_(options.placement) {
    validatePlacement(placement_);
    evaluate_.detail = options.detail;
    evaluate_.detailSeed = options.seed;
    evaluate_.antialiasVoxels = options.antialiasVoxels;
  }

  std::string name() const override { return "gradient"; }
  int channels() const override { return solid_->channels; }

  void evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f>, std::span<float> values) const override {
    // Voxel centres sit at integer + 0.5 of the placement; batches of 256 keep the copy in cache.
    constexpr std::size_t kBatch = 256;
    Vec3f local[kBatch];
    const std::size_t c = std::size_t(solid_->channels);
    for (std::size_t begin = 0; begin < points.size(); begin += kBatch) {
      const std::size_t count = std::min(kBatch, points.size() - begin);
      for (std::size_t i = 0; i < count; ++i)
        local[i] = placement_.toExemplar(points[begin + i]) - Vec3f::Constant(0.5f);
      evaluateGradientSolid(*solid_, std::span<const Vec3f>(local, count), evaluate_, &values[begin * c]);
    }
  }

 private:
  std::shared_ptr<const GradientSolid> solid_;
  SolidPlacement placement_;
  GradientEvaluateOptions evaluate_;
};

}  // namespace

SolidPlacement gradientSolidPlacement(const GradientSolid& solid, const Box3f& bounds) {
  return fitPlacement(bounds, solid.voxels.maxCoeff(), 1.0f);
}

std::unique_ptr<SolidTexture> makeGradientSolidTexture(std::shared_ptr<const GradientSolid> solid,
                                                       const GradientSolidTextureOptions& options) {
  if (!solid) throw ParameterError("solid", "is null");
  solid->checkConsistent();
  return std::make_unique<GradientSolidTexture>(std::move(solid), options);
}

}  // namespace texsynth
