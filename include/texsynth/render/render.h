#pragma once
// The render module: a deterministic CPU rasterizer that shows meshes (per-vertex colours or
// solid textures evaluated at visible surface points), slice montages of volumes, and
// simple primitive meshes for previews.
#include "texsynth/render/primitives.h"
#include "texsynth/render/render_mesh.h"
#include "texsynth/render/slice_montage.h"
#include "texsynth/render/view_up.h"
