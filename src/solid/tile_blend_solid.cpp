#include "texsynth/solid/tile_blend_solid.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/random.h"
#include "texsynth/image/triangle_grid.h"
#include "texsynth/image/window_support.h"
#include "texsynth/solid/tile_deform_solid.h"

namespace texsynth {
namespace {

constexpr int kMaxChannels = 4;

class TriplanarTileBlendSolid final : public SolidTexture {
 public:
  TriplanarTileBlendSolid(const Image& exemplar, const TileBlendSolidOptions& options)
      : gaussianized_(gaussianize(exemplar, options.gaussianization)),
        options_(options),
        tileSize_(options.tileSize > 0 ? options.tileSize : 0.5f * float(std::min(exemplar.width, exemplar.height))) {}

  std::string name() const override { return "tile-blend-triplanar"; }
  int channels() const override { return gaussianized_.gaussian.channels; }

  void evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f> normals,
                      std::span<float> values) const override {
    const int c = channels();
    float planes[3][kMaxChannels], blended[kMaxChannels];
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec3f p = options_.placement.toExemplar(points[i]);
      Vec3f w = stackingWeights(normals.empty() ? Vec3f::Zero() : normals[i], options_.blendSharpness);
      const float* contributions[3];
      float weights[3];
      int count = 0;
      for (int axis = 0; axis < 3; ++axis) {
        if (w[axis] == 0.0f) continue;
        const Vec2f uv = axis == 0 ? Vec2f(p.y(), p.z()) : axis == 1 ? Vec2f(p.x(), p.z()) : Vec2f(p.x(), p.y());
        planeGaussian(axis, uv, planes[count]);
        contributions[count] = planes[count];
        weights[count++] = w[axis];
      }
      // The planes are independent Gaussians: blending them variance-preservingly keeps N(0, 1).
      varianceBlend(contributions, weights, count, c, 0.0f, blended);
      gaussianized_.toColor(blended, &values[i * std::size_t(c)]);
    }
  }

 private:
  // The 2D tile-blend of plane `axis` at (u, v), in Gaussian space (each channel ~ N(0, 1)).
  void planeGaussian(int axis, const Vec2f& uv, float* out) const {
    const Image& g = gaussianized_.gaussian;
    GridTriangle tri = triangleGridLookup(uv.x() / tileSize_, uv.y() / tileSize_);
    sharpenWeights(tri.weight, 3, options_.weightExponent);
    float tiles[3][kMaxChannels];
    const float* values[3] = {tiles[0], tiles[1], tiles[2]};
    for (int k = 0; k < 3; ++k) {
      // Each plane has its own random tile offsets, so the three planes are independent.
      const std::uint64_t key = hashKey(options_.seed, latticeId(tri.vertexI[k], tri.vertexJ[k], axis), 0, 0x50d1);
      const double offsetX = double(uniform01(key)) * g.width, offsetY = double(uniform01(mix64(key))) * g.height;
      g.sampleBilinearWrapped(double(uv.x()) + offsetX, double(uv.y()) + offsetY, tiles[k]);
    }
    varianceBlend(values, tri.weight, 3, g.channels, 0.0f, out);
  }

  GaussianizedExemplar gaussianized_;
  TileBlendSolidOptions options_;
  float tileSize_;
};

}  // namespace

std::unique_ptr<SolidTexture> makeTileBlendSolid(const Image& exemplar, const TileBlendSolidOptions& options) {
  if (exemplar.empty()) throw ParameterError("exemplar", "image is empty");
  if (exemplar.channels > kMaxChannels) throw ParameterError("exemplar", "has more than 4 channels");
  validatePlacement(options.placement);
  requireFiniteAtLeast("tileSize", options.tileSize, 0.0f);
  requireFiniteAtLeast("weightExponent", options.weightExponent, 1.0f);
  validateBlendSharpness(options.blendSharpness);
  return std::make_unique<TriplanarTileBlendSolid>(exemplar, options);  // gaussianize validates its options
}

}  // namespace texsynth
