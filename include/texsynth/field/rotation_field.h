#pragma once
// RotationField: a smooth field of local frames (unit quaternions, global frame -> local frame)
// on a regular grid, as in sketch-guided solid texturing §3. Sampling interpolates the four
// components trilinearly and normalizes, after flipping each corner's sign towards the first
// corner (q and -q are the same rotation).
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/field/field_grid.h"

namespace texsynth {

class RotationField {
 public:
  RotationField() = default;
  // Every node the identity rotation.
  explicit RotationField(const FieldGrid& grid);
  // Takes one unit quaternion per node (x fastest). Throws ParameterError("rotations", ...) on a
  // size mismatch or a non-unit / non-finite quaternion.
  RotationField(const FieldGrid& grid, std::vector<Quatf> rotations);

  const FieldGrid& grid() const { return grid_; }
  const std::vector<Quatf>& rotations() const { return rotations_; }
  const Quatf& at(std::int64_t node) const { return rotations_[std::size_t(node)]; }

  // The rotation at any point (clamped to the grid's box): trilinear, sign-aligned, normalized.
  Quatf sample(const Vec3f& p) const;
  // The local frame (x, y, z axes in world space) at any point.
  Frame frame(const Vec3f& p) const { return Frame::fromQuaternion(sample(p)); }

  // A smoothed copy at half resolution (sign-aligned [1 2 1]/4 filter per axis, then every other
  // node), for coarse synthesis levels.
  RotationField downsampled() const;
  // This field followed by `count` successive downsampled copies (count >= 0).
  std::vector<RotationField> pyramid(int count) const;

 private:
  FieldGrid grid_;
  std::vector<Quatf> rotations_;
};

// Geodesic angle between two rotations in degrees, in [0, 180] (q and -q count as equal).
float rotationAngleDegrees(const Quatf& a, const Quatf& b);

}  // namespace texsynth
