#pragma once
// Simple meshes built in code: for tests, demos and previews when no mesh file is given.
#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

// Axis-aligned box from `min` to `max`: 24 vertices (4 per face, so each face keeps its own
// normal) and 12 triangles, counter-clockwise seen from outside, with outward normals.
// Throws ParameterError("box", ...) unless min < max on every axis.
Mesh makeBoxMesh(const Vec3f& min, const Vec3f& max);

// Latitude/longitude sphere with poles on +-Y: `rings` latitude bands (>= 2) and `segments`
// longitudes (>= 3), counter-clockwise seen from outside, with outward normals.
// Throws ParameterError naming a bad radius, rings or segments.
Mesh makeUvSphereMesh(const Vec3f& center, float radius, int rings, int segments);

}  // namespace texsynth
