#pragma once
// Deterministic CPU rasterizer: shows a mesh (per-vertex colours, or colours evaluated at
// every visible surface point, e.g. from a solid texture) from an automatically fitted
// perspective camera. The image is bitwise identical for any thread count.
#include <functional>
#include <utility>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

// Colours for a batch of visible surface points: world positions and unit normals in,
// one RGB colour in [0,1] per point out (the callee resizes `colors` to points.size()).
using SurfaceColorFunction = std::function<void(const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals,
                                                std::vector<Vec3f>& colors)>;

struct RenderOptions {
  // Output size in pixels; each in [1, 16384].
  int width = 768, height = 768;
  // Camera orbit around the centre of the mesh bounds. For up = +Y: at yaw = pitch = 0 the
  // camera sits on +Z looking towards -Z (x to the right, y up); positive yaw moves the camera
  // towards +X, positive pitch raises it (looking down). Any finite angles.
  float yawDegrees = 30, pitchDegrees = 20;
  // The model's up direction (finite, non-zero; normalized internally): the orbit is turned by
  // upFrame(up) (view_up.h), so yaw turns about `up`, pitch raises the camera towards it and
  // `up` points up in the image. Commands set it from --up or viewUpDirection(mesh).
  Vec3f up{0, 1, 0};
  // Field of view across the smaller image side, in (0, 170).
  float fovDegrees = 35;
  // Empty space kept around the mesh's bounding sphere, as a fraction of its radius; >= 0.
  // The camera distance fits the bounding sphere, so the whole mesh is visible at any angle.
  float margin = 0.05f;
  Vec3f background{1, 1, 1};
  // Shade = ambient + (1 - ambient) * |n . light|; in [0, 1]. Two-sided so open meshes look right.
  float ambient = 0.3f;
  // Key light direction in camera space (x right, y up, z towards the viewer): a headlight
  // from slightly above-left. Normalized internally; must be non-zero.
  Vec3f lightDirection{-0.35f, 0.45f, 1.0f};
  // Anti-aliasing: supersample x supersample samples per pixel, box filtered; in [1, 16],
  // with width * supersample and height * supersample at most 16384.
  int supersample = 2;
  // Interpolate vertex normals (computed area-weighted if the mesh has none); false shades
  // (and reports) flat face normals.
  bool smoothShading = true;
  // Surface colour of a mesh without per-vertex colours (light gray).
  Vec3f defaultColor{0.8f, 0.8f, 0.8f};
};

// Throws ParameterError naming the first invalid option.
void validateRenderOptions(const RenderOptions& options);

// Renders with per-vertex colours (mesh.colors) interpolated, or options.defaultColor if none.
// Returns an RGB image. Throws ParameterError for bad options, InputError("mesh", ...) for an
// invalid mesh (no faces, bad indices, non-finite coordinates).
Image renderMesh(const Mesh& mesh, const RenderOptions& options = {});

// Renders with the colour of every visible sample evaluated by `colorAt`, called exactly once
// with all visible samples' interpolated world points and unit normals (perspective-correct),
// in raster order of the supersampled image.
Image renderMesh(const Mesh& mesh, const SurfaceColorFunction& colorAt, const RenderOptions& options = {});

// Several views side by side (left to right, in the given order), each options.width x
// options.height; yawPitch holds (yawDegrees, pitchDegrees) per view. colorAt may be null
// (per-vertex colours); otherwise it is called once per view.
Image renderViews(const Mesh& mesh, const SurfaceColorFunction* colorAt,
                  const std::vector<std::pair<float, float>>& yawPitch, const RenderOptions& options = {});

// Peak bytes renderViews needs for `views` views (each sample's depth, colour and surface point,
// the views and their joined copy; measured at 1024² and 2048²: about 13 bytes a supersample),
// for checks before any work.
double renderMemoryBytes(const RenderOptions& options, int views);

// RGB images left to right on a white background, `gap` pixels apart and from the border,
// aligned at the top (e.g. surface views and a cut view; gap 0 simply joins them).
Image sideBySide(const std::vector<Image>& images, int gap = 0);

}  // namespace texsynth
