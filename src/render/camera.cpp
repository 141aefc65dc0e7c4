#include "camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "texsynth/render/view_up.h"

namespace texsynth::render_detail {

namespace {

float radians(float degrees) {
  return degrees * std::numbers::pi_v<float> / 180.0f;
}

struct BoundingSphere {
  Vec3f center;
  float radius;
};

// Centre of the bounding box, radius to the farthest vertex: tighter than the box's
// half-diagonal and still independent of the view direction.
BoundingSphere boundingSphere(const Mesh& mesh) {
  Vec3f center = mesh.bounds().center();
  float radiusSquared = 0;
  for (const Vec3f& p : mesh.positions) radiusSquared = std::max(radiusSquared, (p - center).squaredNorm());
  float radius = std::sqrt(radiusSquared);
  // All vertices coincide: every face is degenerate and nothing is drawn; any radius works.
  if (!(radius > 0)) radius = 1;
  return {center, radius};
}

}  // namespace

Camera fitCamera(const Mesh& mesh, const RenderOptions& options, int sampleWidth, int sampleHeight) {
  BoundingSphere sphere = boundingSphere(mesh);
  // Camera-to-world rotation: orbit about +Y by yaw, then raise by pitch (rotation about -X),
  // in the frame that takes +Y to the model's up (the identity for +Y).
  Mat3f cameraToWorld = (Eigen::AngleAxisf(radians(options.yawDegrees), Vec3f::UnitY()) *
                         Eigen::AngleAxisf(-radians(options.pitchDegrees), Vec3f::UnitX()))
                            .toRotationMatrix();
  const Mat3f frame = upFrame(options.up);
  if (frame != Mat3f::Identity()) cameraToWorld = frame * cameraToWorld;
  float halfFov = 0.5f * radians(options.fovDegrees);
  // The sphere seen from distance d spans a half-angle asin(r / d); pick d so that angle
  // leaves `margin` (relative to the radius) inside the field of view.
  float distance = sphere.radius * (1.0f + options.margin) / std::sin(halfFov);

  Camera camera;
  camera.worldToView = cameraToWorld.transpose();
  camera.eye = sphere.center + cameraToWorld * Vec3f(0, 0, distance);
  camera.focal = 0.5f * float(std::min(sampleWidth, sampleHeight)) / std::tan(halfFov);
  camera.centerX = 0.5f * float(sampleWidth);
  camera.centerY = 0.5f * float(sampleHeight);
  return camera;
}

}  // namespace texsynth::render_detail
