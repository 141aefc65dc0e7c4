#pragma once
// Baking a surface synthesis into a texture map: the synthesized colors live on the vertices of
// a retiled mesh, but renderers and game engines want an image in the UV layout of the artist's
// own mesh. Each texel of that layout is mapped to its 3D point on the UV mesh, the point to the
// nearest point of the colored mesh (geometry/surface_projector.h), and the colors of that
// triangle's corners are interpolated there. Charts are then grown by a few texels so mip-maps
// and bilinear filtering do not pull in background.
#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/progress.h"

namespace texsynth {

struct SurfaceBakeOptions {
  int size = 2048;  // texels per side, in [1, 16384]
  // Texels the charts grow by (each pass fills the empty texels next to filled ones with their
  // mean); -1: size / 256, at least 2 (8 at 2048, enough for the mip levels that still show a chart).
  int dilation = -1;
};

// The texture of `colored` (per-vertex colors) in the UV layout of `uvMesh` (its "uv" attribute,
// v up: texel row 0 is v = 1, as OBJ and PLY files mean it). Texels no chart covers after the
// dilation get the mean baked color, so even the coarsest mip-maps stay the texture's color.
// UVs outside [0, 1] are clipped, not wrapped. Overlapping charts: the later triangle wins.
// Deterministic for any thread count. Progress: one stage, one unit per texel row. Throws
// ParameterError("uv", ...) if uvMesh has no 2-component "uv" attribute, ParameterError("colors",
// ...) if colored has no colors, ParameterError("size" / "dilation", ...) for bad options,
// InputError("mesh", ...) for a colored mesh without triangles.
Image bakeVertexColors(const Mesh& uvMesh, const Mesh& colored, const SurfaceBakeOptions& options = {},
                       Progress& progress = noProgress());

}  // namespace texsynth
