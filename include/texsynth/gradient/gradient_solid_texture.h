#pragma once
// A GradientSolid as a SolidTexture, so every consumer (mesh colouring, renders, slices, volumes)
// takes it. It is resolution-independent: a volume at any --resolution evaluates the tricubic there.
#include <memory>

#include "texsynth/gradient/gradient_solid.h"
#include "texsynth/solid/solid_texture.h"

namespace texsynth {

struct GradientSolidTextureOptions {
  // World -> the solid's voxel units is exemplar = (world - origin) * pixelsPerUnit, as every solid.
  SolidPlacement placement;
  bool detail = true;  // add the stored residual grain (if any)
  std::uint64_t seed = 1;
  float antialiasVoxels = 1.0f;
};

// Places the solid so that it spans `bounds` (its longest side on the box's longest side).
SolidPlacement gradientSolidPlacement(const GradientSolid& solid, const Box3f& bounds);

std::unique_ptr<SolidTexture> makeGradientSolidTexture(std::shared_ptr<const GradientSolid> solid,
                                                       const GradientSolidTextureOptions& options);

}  // namespace texsynth
