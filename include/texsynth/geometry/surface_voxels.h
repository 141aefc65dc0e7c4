#pragma once
// The voxels a mesh's surface passes through, on the sampling grid of sampling_grid.h
// (`resolution` voxels along the box's longest side): the request "the whole surface at
// resolution R" that on-demand solid synthesis is measured with.
#include <vector>

#include "texsynth/core/mesh.h"

namespace texsynth {

// Centres (world units) of every grid voxel that some triangle of `mesh` touches, each once,
// in z, y, x order. Triangles are sampled at a spacing below a third of a voxel, so no voxel a
// triangle crosses is missed by more than a sliver. Throws ParameterError("box" | "resolution",
// ...) as samplingGridSize, InputError("mesh", ...) for a mesh without triangles.
std::vector<Vec3f> surfaceVoxelCenters(const Mesh& mesh, const Box3f& box, int resolution);

}  // namespace texsynth
