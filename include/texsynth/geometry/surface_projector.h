#pragma once
// Closest points on a triangle mesh: snaps sketch points to the surface and gives the triangle,
// barycentric weights and interpolated outward normal there (the mesh hierarchy's parent
// lookup uses it too). Also tells whether a point is inside a closed mesh.
#include <memory>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

struct SurfacePoint {
  Vec3f position = Vec3f::Zero();
  Vec3f normal = Vec3f::UnitZ();       // unit, interpolated vertex normal (outward for a closed mesh)
  float distance = 0;                  // from the query point
  int triangle = -1;                   // the mesh triangle the closest point lies on (ties: the lowest index)
  Vec3f barycentric = Vec3f(1, 0, 0);  // weights of that triangle's 3 vertices at `position` (>= 0, sum 1)
};

class SurfaceProjector {
 public:
  // Keeps a copy of the geometry and a uniform bucket grid of triangles (cells about one mean
  // edge wide). Throws InputError("mesh", ...) for a mesh without triangles.
  explicit SurfaceProjector(const Mesh& mesh);
  ~SurfaceProjector();
  SurfaceProjector(SurfaceProjector&&) noexcept;
  SurfaceProjector& operator=(SurfaceProjector&&) noexcept;

  // The exact closest point (ties: the lowest triangle index), whatever the grid. Thread-safe.
  SurfacePoint closestPoint(const Vec3f& p) const;
  // Parity of crossings of a ray towards +x: right for closed (watertight) meshes.
  bool inside(const Vec3f& p) const;
  const Box3f& bounds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace texsynth
