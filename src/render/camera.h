#pragma once
// Internal: the perspective camera that renderMesh fits to a mesh's bounding sphere.
#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth::render_detail {

struct Camera {
  Mat3f worldToView;  // rows: camera right, up, back (the camera looks along -back)
  Vec3f eye;
  float focal = 1;                 // in samples
  float centerX = 0, centerY = 0;  // image centre, in samples

  // Screen position (x right, y down, in samples) and the inverse of the view depth.
  // Only valid for points in front of the camera, which the fit guarantees for the mesh.
  Vec3f project(const Vec3f& world) const {
    Vec3f v = worldToView * (world - eye);
    float inverseDepth = 1.0f / -v.z();
    return {centerX + focal * v.x() * inverseDepth, centerY - focal * v.y() * inverseDepth, inverseDepth};
  }
  Vec3f viewToWorldDirection(const Vec3f& v) const { return worldToView.transpose() * v; }
};

// A camera orbiting the mesh's bounding sphere at (yaw, pitch) about options.up, far enough
// that the whole sphere (plus margin) is visible across the smaller side of a
// sampleWidth x sampleHeight image.
Camera fitCamera(const Mesh& mesh, const RenderOptions& options, int sampleWidth, int sampleHeight);

}  // namespace texsynth::render_detail
