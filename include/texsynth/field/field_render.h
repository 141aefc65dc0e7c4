#pragma once
// A picture of a rotation field: the mesh with its sketch curves (yellow) and the local x, y, z
// axes as red, green and blue glyphs on the surface, next to a cut through the volume whose cap
// carries glyphs of the interior field.
#include <utility>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"
#include "texsynth/field/rotation_field.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth {

struct FieldRenderOptions {
  // Size, supersampling, lighting and up of each view; yaw/pitch are overridden by `views`
  // (and the cut's, cutViewAngles, turned to render.up).
  RenderOptions render;
  // Surface views as (yaw, pitch) in degrees, left to right; may be empty if showCut.
  std::vector<std::pair<float, float>> views{{30, 20}};
  // Glyphs across the mesh's longest side (surface and cut); in [2, 200].
  int glyphsAcross = 14;
  // The cut view: the plane normal to axis cutAxis (0, 1, 2) at fraction cutPosition in (0, 1)
  // of the mesh's extent; the part on the +axis side is removed.
  bool showCut = true;
  int cutAxis = 2;
  float cutPosition = 0.5f;
};

// Throws ParameterError naming the first invalid option.
void validateFieldRenderOptions(const FieldRenderOptions& options);

// Views side by side (surface views, then the cut), each render.width x render.height.
// `curves` are polylines in world space (e.g. the placed curve samples).
Image renderFieldGlyphs(const Mesh& mesh, const RotationField& field, const std::vector<std::vector<Vec3f>>& curves,
                        const FieldRenderOptions& options = {});

}  // namespace texsynth
