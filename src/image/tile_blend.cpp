#include "texsynth/image/tile_blend.h"

#include <algorithm>
#include <vector>

#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/image/triangle_grid.h"
#include "texsynth/image/window_support.h"

namespace texsynth {

namespace {

constexpr int kMaxChannels = 16;

void validate(const Image& exemplar, const TileBlendOptions& o) {
  if (exemplar.empty()) throw ParameterError("exemplar", "image is empty");
  if (exemplar.channels > kMaxChannels)
    throw ParameterError("exemplar", "at most " + std::to_string(kMaxChannels) + " channels supported");
  requireFiniteAtLeast("tileSize", o.tileSize, 0.0f);
  requireFiniteAtLeast("weightExponent", o.weightExponent, 1.0f);
}

}  // namespace

TileBlendTexture::TileBlendTexture(const Image& exemplar, const TileBlendOptions& options) : options_(options) {
  validate(exemplar, options);
  gaussianized_ = gaussianize(exemplar, options.gaussianization);
  tileSize_ = options.tileSize > 0 ? options.tileSize : 0.5f * float(std::min(exemplar.width, exemplar.height));
}

void TileBlendTexture::vertexOffset(std::int64_t i, std::int64_t j, double offset[2]) const {
  std::uint64_t key = hashKey(options_.seed, latticeId(i, j), 0, 0xb1e0);
  offset[0] = double(uniform01(key)) * gaussianized_.gaussian.width;
  offset[1] = double(uniform01(mix64(key))) * gaussianized_.gaussian.height;
}

void TileBlendTexture::sample(double x, double y, float* color) const {
  const Image& g = gaussianized_.gaussian;
  GridTriangle tri = triangleGridLookup(x / tileSize_, y / tileSize_);
  sharpenWeights(tri.weight, 3, options_.weightExponent);
  float tiles[3][kMaxChannels], blended[kMaxChannels];
  const float* values[3] = {tiles[0], tiles[1], tiles[2]};
  for (int k = 0; k < 3; ++k) {
    double offset[2];
    vertexOffset(tri.vertexI[k], tri.vertexJ[k], offset);
    g.sampleBilinearWrapped(x + offset[0], y + offset[1], tiles[k]);
  }
  varianceBlend(values, tri.weight, 3, g.channels, 0.0f, blended);
  gaussianized_.toColor(blended, color);
}

Image TileBlendTexture::synthesizeWindow(std::int64_t x0, std::int64_t y0, int width, int height) const {
  requireWindow(x0, y0, width, height);
  Image out(width, height, gaussianized_.gaussian.channels);
  parallelForChunks(0, height, kRowChunk, [&](std::int64_t rowBegin, std::int64_t rowEnd) {
    for (std::int64_t y = rowBegin; y < rowEnd; ++y)
      for (int x = 0; x < width; ++x) sample(double(x0 + x) + 0.5, double(y0 + y) + 0.5, out.pixel(x, int(y)));
  });
  return out;
}

Image synthesizeTileBlend(const Image& exemplar, const TileBlendOptions& options, std::int64_t x0, std::int64_t y0,
                          int width, int height) {
  return TileBlendTexture(exemplar, options).synthesizeWindow(x0, y0, width, height);
}

}  // namespace texsynth
