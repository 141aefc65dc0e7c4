#include "texsynth/field/rotation_field.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

// Quaternion components as a 4-vector (x, y, z, w: Eigen's storage order).
Vec4f components(const Quatf& q) {
  return q.coeffs();
}

// Flips b to the same hemisphere as a (q and -q are one rotation).
Vec4f aligned(const Vec4f& reference, const Vec4f& b) {
  return reference.dot(b) < 0 ? Vec4f(-b) : b;
}

}  // namespace

float rotationAngleDegrees(const Quatf& a, const Quatf& b) {
  // 2 atan2(|a - b|, |a + b|) in double: acos of the dot product loses everything below ~0.05
  // degrees in float, exactly where tests compare nearly equal fields.
  Eigen::Vector4d u = a.coeffs().cast<double>().normalized(), v = b.coeffs().cast<double>().normalized();
  if (u.dot(v) < 0) v = -v;
  double halfAngle = 2 * std::atan2((u - v).norm(), (u + v).norm());
  return float(2 * halfAngle * 180 / 3.14159265358979323846);
}

RotationField::RotationField(const FieldGrid& grid)
    : grid_(grid), rotations_(std::size_t(grid.nodeCount()), Quatf::Identity()) {}

RotationField::RotationField(const FieldGrid& grid, std::vector<Quatf> rotations)
    : grid_(grid), rotations_(std::move(rotations)) {
  if (std::int64_t(rotations_.size()) != grid.nodeCount())
    throw ParameterError("rotations", "has " + std::to_string(rotations_.size()) + " entries for " +
                                          std::to_string(grid.nodeCount()) + " grid nodes");
  for (const Quatf& q : rotations_)
    if (!q.coeffs().allFinite() || std::abs(q.squaredNorm() - 1.0f) > 1e-3f)
      throw ParameterError("rotations", "must be finite unit quaternions");
}

Quatf RotationField::sample(const Vec3f& p) const {
  const FieldGrid::Corners cell = grid_.corners(p);
  const Vec4f reference = components(at(cell.node[0]));
  Vec4f sum = Vec4f::Zero();
  float bestWeight = -1;
  Vec4f nearest = reference;
  for (int corner = 0; corner < 8; ++corner) {
    const float w = cell.weight[corner];
    Vec4f q = aligned(reference, components(at(cell.node[corner])));
    sum += w * q;
    if (w > bestWeight) bestWeight = w, nearest = q;
  }
  // Opposing corners can cancel: fall back to the nearest corner's rotation.
  float norm = sum.norm();
  Vec4f unit = norm > 1e-6f ? Vec4f(sum / norm) : nearest;
  return Quatf(unit[3], unit[0], unit[1], unit[2]);
}

RotationField RotationField::downsampled() const {
  // Separable sign-aligned [1 2 1]/4 smoothing, one axis at a time, then every other node.
  std::vector<Vec4f> values(rotations_.size());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = components(rotations_[i]);
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Vec4f> next(values.size());
    for (std::int64_t i = 0; i < grid_.nodeCount(); ++i) {
      Vec3i c = grid_.coordinates(i);
      Vec4f centre = values[std::size_t(i)], sum = 2 * centre;
      float weight = 2;
      for (int d : {-1, 1}) {
        Vec3i n = c;
        n[axis] += d;
        if (n[axis] < 0 || n[axis] >= grid_.nodes[axis]) continue;
        sum += aligned(centre, values[std::size_t(grid_.index(n.x(), n.y(), n.z()))]);
        weight += 1;
      }
      next[std::size_t(i)] = sum / weight;
    }
    values = std::move(next);
  }
  FieldGrid coarse = coarserGrid(grid_);
  std::vector<Quatf> rotations(std::size_t(coarse.nodeCount()));
  for (std::int64_t i = 0; i < coarse.nodeCount(); ++i) {
    Vec3i c = coarse.coordinates(i);
    Vec3i f = (2 * c).cwiseMin(grid_.nodes - Vec3i::Ones());
    Vec4f q = values[std::size_t(grid_.index(f.x(), f.y(), f.z()))];
    // Where smoothing cancelled out, keep the original rotation.
    if (q.norm() < 1e-6f) q = components(at(grid_.index(f.x(), f.y(), f.z())));
    q.normalize();
    rotations[std::size_t(i)] = Quatf(q[3], q[0], q[1], q[2]);
  }
  return RotationField(coarse, std::move(rotations));
}

std::vector<RotationField> RotationField::pyramid(int count) const {
  if (count < 0) throw ParameterError("count", "must be non-negative");
  std::vector<RotationField> levels{*this};
  for (int l = 0; l < count; ++l) levels.push_back(levels.back().downsampled());
  return levels;
}

}  // namespace texsynth
