#pragma once
// Orientation sources for lazy solid synthesis: adapters from a RotationField (and a constant
// rotation) to the LazyOrientation function that LazySolid takes, so lazy_solid.h needs no
// field types.
#include <memory>
#include <string>
#include <vector>

#include "texsynth/core/hash.h"
#include "texsynth/field/rotation_field.h"
#include "texsynth/solid/lazy_solid.h"
#include "texsynth/solid/solid_texture.h"

namespace texsynth {

// The field at every level: level l (0 = coarsest) samples RotationField::pyramid's copy
// downsampled L-1-l times, at the world point of the voxel under `placement`.
inline LazyOrientation lazyOrientationFromField(const RotationField& field, const SolidPlacement& placement,
                                                int levels) {
  auto pyramid = std::make_shared<const std::vector<RotationField>>(field.pyramid(levels - 1));
  return [pyramid, placement, levels](int level, const Vec3f& finestPosition) {
    const Vec3f world = placement.origin + finestPosition / placement.pixelsPerUnit;
    return (*pyramid)[std::size_t(levels - 1 - level)].sample(world);
  };
}

// LazySolidOptions::orientationKey for lazyOrientationFromField(field, placement, levels): a
// digest of the field's grid and rotations and of the placement.
inline std::string lazyOrientationKey(const RotationField& field, const SolidPlacement& placement, int levels) {
  Hasher hasher;
  const FieldGrid& grid = field.grid();
  hasher.string("rotation-field").value(grid.spacing).value(placement.pixelsPerUnit).value(levels);
  for (int a = 0; a < 3; ++a) hasher.value(grid.origin[a]).value(grid.nodes[a]).value(placement.origin[a]);
  for (const Quatf& q : field.rotations()) hasher.value(q.w()).value(q.x()).value(q.y()).value(q.z());
  return hasher.hex();
}

// One rotation everywhere (tests, slab demos).
inline LazyOrientation constantOrientation(const Quatf& rotation) {
  const Quatf q = rotation.normalized();
  return [q](int, const Vec3f&) { return q; };
}

}  // namespace texsynth
