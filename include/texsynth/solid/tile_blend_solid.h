#pragma once
// Tile-blend solid (beyond the paper): the 3D analogue of Heitz & Neyret's histogram-
// preserving tiling and blending, built triplanar. On each of the planes normal to x, y and z
// the Gaussianized 2D exemplar is tile-blended over its own triangle grid (random offsets per
// lattice vertex and per plane); the three Gaussian-space values are blended again with the
// eq. 3 normal weights and the variance-preserving normalization, then mapped back through
// the exemplar's inverse histogram LUT (Deliot & Heitz 2019). So the result keeps the
// exemplar histogram, shows no repetition and no deformation, and only the 2D exemplar (in
// Gaussian space) is kept in memory.
#include <cstdint>
#include <memory>

#include "texsynth/core/image.h"
#include "texsynth/image/histogram_gaussianization.h"
#include "texsynth/solid/solid_texture.h"

namespace texsynth {

struct TileBlendSolidOptions {
  SolidPlacement placement;  // world -> exemplar pixels (see fitPlacement)
  // Triangle edge in exemplar pixels (finite, >= 0); 0 picks half the exemplar's smaller side.
  float tileSize = 0.0f;
  // Exponent on the in-plane barycentric weights (finite, >= 1), as 2D tile-blend.
  float weightExponent = 2.0f;
  // p of eq. 3 for the three planes (finite, in (0, 64]). Without normals (slices, volumes)
  // the three planes get equal weights.
  float blendSharpness = 4.0f;
  GaussianizationOptions gaussianization;
  std::uint64_t seed = 1;
};

// Throws ParameterError naming the bad option ("placement.*", "tileSize", "weightExponent",
// "blendSharpness", "lutSize", "gaussianRange") or "exemplar" (empty, > 4 channels).
std::unique_ptr<SolidTexture> makeTileBlendSolid(const Image& exemplar, const TileBlendSolidOptions& options = {});

}  // namespace texsynth
