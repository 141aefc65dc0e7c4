#pragma once
// Linear-algebra vocabulary (Eigen) and orientation frames built from quaternions.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>

namespace texsynth {

using Vec2f = Eigen::Vector2f;
using Vec3f = Eigen::Vector3f;
using Vec4f = Eigen::Vector4f;
using Vec2i = Eigen::Vector2i;
using Vec3i = Eigen::Vector3i;
using Mat3f = Eigen::Matrix3f;
using Mat4f = Eigen::Matrix4f;
using Quatf = Eigen::Quaternionf;

// Axis-aligned box.
struct Box3f {
  Vec3f min = Vec3f::Constant(std::numeric_limits<float>::max());
  Vec3f max = Vec3f::Constant(-std::numeric_limits<float>::max());
  void extend(const Vec3f& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool valid() const { return (max.array() >= min.array()).all(); }
  Vec3f center() const { return 0.5f * (min + max); }
  Vec3f size() const { return max - min; }
};

// An orthonormal local frame: the columns of a rotation matrix.
struct Frame {
  Vec3f x = Vec3f::UnitX(), y = Vec3f::UnitY(), z = Vec3f::UnitZ();

  static Frame fromQuaternion(const Quatf& q);
  // A frame whose z axis is `normal` (x chosen stably from the normal alone).
  static Frame fromNormal(const Vec3f& normal);
  Quatf toQuaternion() const;
  Vec3f toLocal(const Vec3f& v) const { return {v.dot(x), v.dot(y), v.dot(z)}; }
  Vec3f toWorld(const Vec3f& v) const { return v.x() * x + v.y() * y + v.z() * z; }
};

}  // namespace texsynth
