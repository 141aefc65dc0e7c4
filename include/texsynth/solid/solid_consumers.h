#pragma once
// Consumers written once against SolidTexture: per-vertex mesh colours, a per-pixel colour
// function for renderMesh, axis-aligned slices and whole sampled volumes.
//
// Slices and volumes sample a regular grid over a box: `resolution` voxels along the box's
// longest side, the other sides proportionally (at least 1), samples at voxel centres. Grid
// axis a, index i sits at  box.min[a] + ((i + 0.5) / n[a]) * box.size()[a], so slice
// `sampleSlice(s, box, axis, (k + 0.5f) / n[axis], resolution)` equals plane k of
// `sampleVolume(s, box, resolution)` exactly. Slices are sampled without normals.
#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/volume.h"
#include "texsynth/geometry/sampling_grid.h"  // samplingGridSize
#include "texsynth/render/render_mesh.h"
#include "texsynth/solid/solid_texture.h"

namespace texsynth {

// Sets mesh.colors to the solid's colour at every vertex (using the vertex normals;
// computed first if the mesh has none). Throws InputError("mesh", ...) for an invalid mesh.
void colorMeshVertices(Mesh& mesh, const SolidTexture& solid);

// A colour function for renderMesh that evaluates the solid at every visible surface point
// (with its interpolated normal). `solid` must outlive the returned function.
SurfaceColorFunction surfaceColorFunction(const SolidTexture& solid);

// The slice normal to `axis` (0 = x, 1 = y, 2 = z) at `position` in [0, 1] across the box.
// Image axes (u right, v down) as in eval: normal x -> (y, z), normal y -> (x, z), normal
// z -> (x, y). Returns all channels() of the solid. Throws ParameterError("axis" |
// "position" | "box" | "resolution", ...).
Image sampleSlice(const SolidTexture& solid, const Box3f& box, int axis, float position, int resolution);

// The whole grid as a volume with channels() channels, computed in parallel over z-slabs.
Volume sampleVolume(const SolidTexture& solid, const Box3f& box, int resolution);

}  // namespace texsynth
