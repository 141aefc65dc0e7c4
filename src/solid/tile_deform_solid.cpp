#include "texsynth/solid/tile_deform_solid.h"

#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

// The two image coordinates of a point stacked along `axis` (0 = x, 1 = y, 2 = z).
Vec2f stackedImageCoordinates(const Vec3f& p, int axis) {
  if (axis == 0) return {p.y(), p.z()};
  if (axis == 1) return {p.x(), p.z()};
  return {p.x(), p.y()};
}

class VolumeTileDeformSolid final : public SolidTexture {
 public:
  VolumeTileDeformSolid(Volume exemplar, const TileDeformSolidOptions& options)
      : exemplar_(std::move(exemplar)), placement_(options.placement), deformation_(options.deformation) {}

  std::string name() const override { return "tile-deform-volume"; }
  int channels() const override { return exemplar_.channels; }

  void evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f>, std::span<float> values) const override {
    const std::size_t c = std::size_t(exemplar_.channels);
    GridDeformation3d::CellCache cache;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec3f q = deformation_.map(placement_.toExemplar(points[i]), cache);
      exemplar_.sampleTrilinearWrapped(q.x(), q.y(), q.z(), &values[i * c]);
    }
  }

 private:
  Volume exemplar_;
  SolidPlacement placement_;
  GridDeformation3d deformation_;
};

class StackedTileDeformSolid final : public SolidTexture {
 public:
  StackedTileDeformSolid(Image exemplar, const TileDeformSolidOptions& options)
      : exemplar_(std::move(exemplar)),
        placement_(options.placement),
        deformation_(options.deformation),
        stacking_(options.stacking),
        sharpness_(options.blendSharpness) {}

  std::string name() const override { return "tile-deform-stacked"; }
  int channels() const override { return exemplar_.channels; }

  void evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f> normals,
                      std::span<float> values) const override {
    const int c = exemplar_.channels;
    float sample[4];
    GridDeformation3d::CellCache cache;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec3f q = deformation_.map(placement_.toExemplar(points[i]), cache);
      float* out = &values[i * std::size_t(c)];
      if (stacking_ != StackAxes::All) {
        const Vec2f uv = stackedImageCoordinates(q, int(stacking_));
        exemplar_.sampleBilinearWrapped(uv.x(), uv.y(), out);
        continue;
      }
      const Vec3f w = stackingWeights(normals.empty() ? Vec3f::Zero() : normals[i], sharpness_);
      for (int k = 0; k < c; ++k) out[k] = 0.0f;
      for (int axis = 0; axis < 3; ++axis) {
        if (w[axis] == 0.0f) continue;  // one sample instead of three on axis-aligned faces
        const Vec2f uv = stackedImageCoordinates(q, axis);
        exemplar_.sampleBilinearWrapped(uv.x(), uv.y(), sample);
        for (int k = 0; k < c; ++k) out[k] += w[axis] * sample[k];
      }
    }
  }

 private:
  Image exemplar_;
  SolidPlacement placement_;
  GridDeformation3d deformation_;
  StackAxes stacking_;
  float sharpness_;
};

}  // namespace

Vec3f stackingWeights(const Vec3f& normal, float p) {
  const Vec3f squared = normal.cwiseAbs2();
  const float largest = squared.maxCoeff();
  if (!normal.allFinite() || !(largest > 0.0f)) return Vec3f::Constant(1.0f / 3.0f);
  // (n_i^2)^p, scaled by the largest first so high p cannot underflow all three to zero.
  Vec3f w;
  for (int a = 0; a < 3; ++a) w[a] = std::pow(squared[a] / largest, p);
  return w / w.sum();
}

void validateTileDeformSolid(const TileDeformSolidOptions& options) {
  validatePlacement(options.placement);
  validateGridDeformation(options.deformation);
  validateBlendSharpness(options.blendSharpness);
}

void validateBlendSharpness(float p) {
  if (!(p > 0.0f && p <= 64.0f)) throw ParameterError("blendSharpness", "must be in (0, 64]");
}

std::unique_ptr<SolidTexture> makeTileDeformSolid(Volume exemplar, const TileDeformSolidOptions& options) {
  if (exemplar.empty()) throw ParameterError("exemplar", "volume is empty");
  validateTileDeformSolid(options);
  return std::make_unique<VolumeTileDeformSolid>(std::move(exemplar), options);
}

std::unique_ptr<SolidTexture> makeStackedTileDeformSolid(Image exemplar, const TileDeformSolidOptions& options) {
  if (exemplar.empty()) throw ParameterError("exemplar", "image is empty");
  if (exemplar.channels > 4) throw ParameterError("exemplar", "has more than 4 channels");
  validateTileDeformSolid(options);
  return std::make_unique<StackedTileDeformSolid>(std::move(exemplar), options);
}

}  // namespace texsynth
