#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "surface_flow_fields.h"
#include "texsynth/core/random.h"

namespace texsynth::flow_detail {
namespace {

Vec3f tangentPart(const Vec3f& v, const Vec3f& normal) {
  return v - v.dot(normal) * normal;
}

}  // namespace

std::vector<Vec3f> swirlVelocities(const SurfaceFlowMesh& target, float strength, std::uint64_t seed) {
  const Mesh& mesh = *target.mesh;
  const Box3f box = mesh.bounds();
  const Vec3f centre = box.center();
  // Wavelength ~ the diagonal / 1.5: a few eddies across the mesh, each many vertices wide.
  const float diagonal = box.size().norm();
  const float k = diagonal > 0 ? 1.5f * 2 * std::numbers::pi_v<float> / diagonal : 0.0f;
  // psi = sum_i sin(k a_i . (p - centre) + phase_i) with the a_i the axes of a random rotation
  // (Shoemake's uniform quaternion): orthogonal waves, so no direction dominates.
  const float tau = 2 * std::numbers::pi_v<float>;
  const float u1 = uniform01(hashKey(seed, 0)), u2 = uniform01(hashKey(seed, 1)), u3 = uniform01(hashKey(seed, 2));
  const Quatf rotation(std::sqrt(u1) * std::cos(tau * u3), std::sqrt(1 - u1) * std::sin(tau * u2),
                       std::sqrt(1 - u1) * std::cos(tau * u2), std::sqrt(u1) * std::sin(tau * u3));
  const Mat3f axes = rotation.normalized().toRotationMatrix();
  std::array<float, 3> phases;
  for (int i = 0; i < 3; ++i) phases[std::size_t(i)] = tau * uniform01(hashKey(seed, std::uint64_t(3 + i)));

  std::vector<Vec3f> velocities = perVertex(mesh.vertexCount(), [&](std::size_t v) {
    const Vec3f p = mesh.positions[v] - centre;
    Vec3f gradient = Vec3f::Zero();
    for (int i = 0; i < 3; ++i) gradient += k * std::cos(k * axes.col(i).dot(p) + phases[std::size_t(i)]) * axes.col(i);
    // n x grad = n x (tangent part of grad): the normal component drops out.
    return Vec3f(mesh.normals[v].cross(gradient));
  });
  float largest = 0;
  for (const Vec3f& v : velocities) largest = std::max(largest, v.norm());
  if (largest > 0)
    for (Vec3f& v : velocities) v *= strength * target.spacing / largest;
  return velocities;
}

std::vector<Vec3f> downhillVelocities(const SurfaceFlowMesh& target, const Vec3f& up, float strength) {
  const Vec3f down = -up.normalized() * (strength * target.spacing);
  return perVertex(target.mesh->vertexCount(),
                   [&](std::size_t v) { return tangentPart(down, target.mesh->normals[v]); });
}

std::vector<Vec3f> alongFieldVelocities(const SurfaceFlowMesh& target, float strength) {
  const float speed = strength * target.spacing;
  return perVertex(target.mesh->vertexCount(), [&](std::size_t v) {
    return Vec3f(speed * tangentPart(target.fieldUp[v], target.mesh->normals[v]));
  });
}

}  // namespace texsynth::flow_detail
