#pragma once
// Which way is up when a mesh is shown: the rule every command that renders a mesh uses for
// RenderOptions::up when the user gives no --up. Deterministic, and cheap (150 passes over the
// vertices: about 20 ms for CGAL's 37K-vertex bunny).
#include <utility>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

// How much of the bounding box's face below `up` the mesh stands on, in [0, 1]: the area of the
// convex hull of the vertices within kFloorBand (a fraction of the box's diagonal) of a floor
// that touches the mesh from below, measured in the face's plane and divided by the face's area;
// the widest of 25 floors, level or leaning by up to kFloorTilt degrees towards the face's axes
// (so feet that are not quite level still count: CGAL's pig). `up` is one of the six axis
// directions, given as the axis (0, 1, 2) and its sign. 0 for an empty mesh or a face of zero
// area. On CGAL's meshes: below the feet or base of the cow, bunny, armadillo, dinosaur and pig
// 0.18 to 0.39; on any other face of those at most 0.11 (the armadillo's side), the rest under
// 0.07; on every face of the rearing elephant, which stands on no face, at most 0.05.
inline constexpr float kFloorBand = 0.0075f, kFloorTilt = 3.0f;
float floorFootprint(const Mesh& mesh, int axis, bool positive);

// The up direction for views of `mesh` (a unit axis direction): a model built or scanned
// standing on a floor touches the face of its bounding box below it over a wide area (its feet
// or its base), so the view stands it on the face with the widest floorFootprint, if that is at
// least kFloorFootprint (CGAL's dinosaur comes out +Z up, its pig -Y up, the cow, bunny and
// armadillo +Y up; the machined part fandisk -Y up, resting on its large flat face). Otherwise
// world +Y (a sphere; CGAL's rearing elephant). Ties go to the first of +Y, +Z, +X, -Y, -Z, -X,
// so a box keeps +Y. Only the six axis directions are candidates, and turning a mesh by quarter
// turns turns its up alike: meshes are built axis-aligned, and their principal axes are no
// guide to the up (the bunny's longest axis is 41 degrees off it, the dinosaur's 33). A mesh
// turned to an arbitrary orientation touches no face over a real area and keeps +Y: give the
// up explicitly for those.
inline constexpr float kFloorFootprint = 0.1f;
Vec3f viewUpDirection(const Mesh& mesh);

// The rotation that takes world +Y to `up` (normalized; must be finite and non-zero): the
// identity for +Y, a half turn about +X for -Y, else the shortest arc. RenderOptions' camera
// orbits in this frame, so yaw turns about `up`.
Mat3f upFrame(const Vec3f& up);

// (yaw, pitch) in degrees about `up` of the camera that (yaw, pitch) about world +Y places: the
// same viewing direction (e.g. cutViewAngles, which are for +Y, on a model shown with another
// up), with the image upright for `up`. Returns the angles unchanged for up = +Y.
std::pair<float, float> anglesAboutUp(const Vec3f& up, std::pair<float, float> yawPitchAboutY);

}  // namespace texsynth
