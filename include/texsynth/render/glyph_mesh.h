#pragma once
// Annotation geometry for renders: thin sticks, polylines and axis glyphs, built
// as coloured triangles (with flat normals) and appended to a mesh, so the ordinary rasterizer
// draws them with correct occlusion. Used for rotation-field glyphs and sketch curves.
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

// Glyph colours of the local x, y and z axes.
inline const Vec3f kAxisColors[3] = {{0.90f, 0.12f, 0.10f}, {0.10f, 0.70f, 0.15f}, {0.12f, 0.30f, 0.95f}};

// A copy of `mesh` with every vertex coloured `color` and normals present, ready to take
// appended annotation geometry.
Mesh coloredCopy(const Mesh& mesh, const Vec3f& color);

// A square prism from `from` to `to` with half-width `radius` (both ends capped). Nothing is
// added for a zero-length stick. The mesh must carry colours and normals for all vertices
// (coloredCopy, or an empty mesh); throws ParameterError("mesh", ...) otherwise.
void appendStick(Mesh& mesh, const Vec3f& from, const Vec3f& to, float radius, const Vec3f& color);

// One stick per segment, with a small cube at every joint so bends look closed.
void appendPolyline(Mesh& mesh, const std::vector<Vec3f>& points, float radius, const Vec3f& color);

// Three sticks from `center` along frame.x, frame.y, frame.z (red, green, blue), each `length`
// long; `centered` draws them through the centre instead (length / 2 each way).
void appendAxisGlyph(Mesh& mesh, const Vec3f& center, const Frame& frame, float length, float radius,
                     bool centered = false);

}  // namespace texsynth
