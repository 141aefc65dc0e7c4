#pragma once
// Tile-blend: histogram-preserving tiling and blending (Heitz & Neyret 2018) with the 1D
// per-channel Gaussianization of Deliot & Heitz 2019.
//
// The output plane is covered by an equilateral triangle grid (edge = tileSize pixels). Each
// lattice vertex gets a random offset into the exemplar (hashKey(seed, latticeId(i, j))); a
// point blends the three tiles of its triangle's vertices, with barycentric weights, in
// Gaussian space with the variance-preserving blend, then maps back through T⁻¹. The result
// keeps the exemplar's histogram, has no visible deformation, and is random-access: any
// window is bit-identical to the same region of a larger output.
#include <cstdint>

#include "texsynth/core/image.h"
#include "texsynth/image/histogram_gaussianization.h"

namespace texsynth {

struct TileBlendOptions {
  // Triangle edge in output pixels (> 0); 0 picks half the exemplar's smaller side, which
  // keeps each tile's content coherent while breaking the exemplar's period.
  float tileSize = 0;
  // Exponent on the barycentric weights (>= 1): 1 is the paper's plain blend; larger values
  // narrow the transition zones.
  float weightExponent = 2.0f;
  GaussianizationOptions gaussianization = {};
  std::uint64_t seed = 1;
};

// A ready-to-sample tile-blend texture; owns the Gaussianized exemplar.
class TileBlendTexture {
 public:
  // Throws ParameterError naming the option (tileSize, weightExponent, lutSize, ...) or
  // "exemplar" (empty).
  TileBlendTexture(const Image& exemplar, const TileBlendOptions& options);

  float tileSize() const { return tileSize_; }
  const GaussianizedExemplar& gaussianized() const { return gaussianized_; }

  // Exemplar offset (pixels, in [0, width) x [0, height)) of lattice vertex (i, j).
  void vertexOffset(std::int64_t i, std::int64_t j, double offset[2]) const;
  // Color at output point (x, y): random access to single points.
  void sample(double x, double y, float* color) const;
  // The width x height window whose top-left pixel is (x0, y0).
  Image synthesizeWindow(std::int64_t x0, std::int64_t y0, int width, int height) const;

 private:
  GaussianizedExemplar gaussianized_;
  TileBlendOptions options_;
  float tileSize_;
};

// One-off: the window (x0, y0, width, height) of the infinite tile-blend texture.
Image synthesizeTileBlend(const Image& exemplar, const TileBlendOptions& options, std::int64_t x0, std::int64_t y0,
                          int width, int height);

}  // namespace texsynth
