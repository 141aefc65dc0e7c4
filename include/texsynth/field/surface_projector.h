#pragma once
// Closest points on a triangle mesh: snaps sketch points to the surface and gives the
// interpolated outward normal there. Also tells whether a point is inside a closed mesh.
#include <memory>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

struct SurfacePoint {
  Vec3f position = Vec3f::Zero();
  Vec3f normal = Vec3f::UnitZ();  // unit, interpolated vertex normal (outward for a closed mesh)
  float distance = 0;             // from the query point
};

class SurfaceProjector {
 public:
  // Keeps a copy of the geometry and a uniform bucket grid of triangles. Throws
  // InputError("mesh", ...) for a mesh without triangles.
  explicit SurfaceProjector(const Mesh& mesh);
  ~SurfaceProjector();
  SurfaceProjector(SurfaceProjector&&) noexcept;
  SurfaceProjector& operator=(SurfaceProjector&&) noexcept;

  SurfacePoint closestPoint(const Vec3f& p) const;
  // Parity of crossings of a ray towards +x: right for closed (watertight) meshes.
  bool inside(const Vec3f& p) const;
  const Box3f& bounds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace texsynth
