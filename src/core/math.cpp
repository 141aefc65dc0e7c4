#include "texsynth/core/math.h"

#include <cmath>

namespace texsynth {

Frame Frame::fromQuaternion(const Quatf& q) {
  Mat3f r = q.normalized().toRotationMatrix();
  return {r.col(0), r.col(1), r.col(2)};
}

Frame Frame::fromNormal(const Vec3f& normal) {
  Vec3f z = normal.normalized();
  // Duff et al. 2017 branchless orthonormal basis: continuous except at one pole.
  float sign = std::copysign(1.0f, z.z());
  float a = -1.0f / (sign + z.z());
  float b = z.x() * z.y() * a;
  Vec3f x(1.0f + sign * z.x() * z.x() * a, sign * b, -sign * z.x());
  Vec3f y(b, sign + z.y() * z.y() * a, -z.y());
  return {x, y, z};
}

Quatf Frame::toQuaternion() const {
  Mat3f r;
  r.col(0) = x;
  r.col(1) = y;
  r.col(2) = z;
  return Quatf(r).normalized();
}

}  // namespace texsynth
