#pragma once
// Tile-deform solid textures (Chen, Johan & Mueller-Wittig, "Simple and efficient
// example-based texture synthesis using tiling and deformation", §4).
//   Method 1: a 3D exemplar volume, tiled; the 3D grid deformation picks where to sample it
//             (trilinear, wrapping).
//   Method 2: a 2D exemplar stacked along x, y or z (the colour at p is the image at the
//             deformed point's two in-plane coordinates), or along all three axes with the
//             three results blended per point by eq. 3. Only the 2D image is kept in memory.
// Random access: every point is evaluated on its own, from its coordinates (and normal) only.
#include <memory>

#include "texsynth/core/image.h"
#include "texsynth/core/volume.h"
#include "texsynth/solid/grid_deformation_3d.h"
#include "texsynth/solid/solid_texture.h"

namespace texsynth {

// Stacking direction(s) of method 2. Image axes per stacking axis (as eval's slices):
// x -> image (u, v) = (y, z); y -> (x, z); z -> (x, y).
enum class StackAxes { X, Y, Z, All };

struct TileDeformSolidOptions {
  SolidPlacement placement;             // world -> exemplar pixels (see fitPlacement)
  GridDeformationOptions deformation;   // the 3D grid deformation (λ = 0: plain tiling)
  StackAxes stacking = StackAxes::All;  // method 2 only
  // p of eq. 3 (method 2, all axes), finite and in (0, 64]. Larger p blends over a narrower
  // band of normals around the diagonals (sharper transitions, less ghosting); 4 looked best
  // on GIMP marble/wood (fewer double images than 1-2, no visible seams unlike 16).
  float blendSharpness = 4.0f;
};

// Eq. 3: w_i = (n . e_i)^(2p), normalized to sum 1. A zero or non-finite normal gets equal
// weights (1/3 each) — the rule used for volume and slice requests, which carry no normal.
Vec3f stackingWeights(const Vec3f& normal, float p);
// Throws ParameterError("blendSharpness", ...) unless p is in (0, 64].
void validateBlendSharpness(float p);

// Throws ParameterError naming the bad option ("placement.*", "deformation.*",
// "blendSharpness").
void validateTileDeformSolid(const TileDeformSolidOptions& options);

// Method 1. Throws ParameterError("exemplar", ...) for an empty volume.
std::unique_ptr<SolidTexture> makeTileDeformSolid(Volume exemplar, const TileDeformSolidOptions& options = {});
// Method 2. Throws ParameterError("exemplar", ...) for an empty image.
std::unique_ptr<SolidTexture> makeStackedTileDeformSolid(Image exemplar, const TileDeformSolidOptions& options = {});

}  // namespace texsynth
