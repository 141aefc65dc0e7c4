#pragma once
// Velocity fields for flow animation on a mesh surface: a tangent vector per vertex of the
// synthesis mesh (the finest retiled level), in world units per frame.
//
// SPEC = NAME[:key=value,...] or a file:
//   along-field:strength=0.5     along the orientation field's up direction (the exemplar's up:
//                                the sketch-designed field with --field/--sketch, else the
//                                smooth field following --up)
//   downhill:strength=0.5        down the surface, along the tangent part of -up (lava, rain):
//                                fastest where the surface is vertical, still on flat tops
//   swirl:strength=0.5,seed=1    n x grad(psi) for a smooth stream function psi (a few
//                                low-frequency waves over the bounding box): divergence-free
//                                eddies over the whole surface
// strength is the largest speed, in vertex spacings (the finest level's spacing, about one
// exemplar pixel) per frame; finite, negative reverses the flow. seed is an integer in
// 0 .. 2^64 - 1. SPEC is a file when its NAME is no preset and it looks like a path ('/', '.'
// or '%' in it, or an existing file). A file gives one velocity per vertex of the INPUT mesh (the user's,
// before retiling): text, one line "vx vy vz" (world units per frame) per vertex in the mesh
// file's order, '#' comments and blank lines skipped; it is carried to the synthesis mesh at
// each vertex's closest point on the input mesh (barycentric), then projected onto the tangent
// plane (the input mesh needs triangles, not normals). A printf-style frame number in the name
// (flow/%04d.txt, as for ImageFlow) makes it time-varying: frame t reads file number t. Every
// velocity is multiplied by `scale`.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

struct SurfaceFlowOptions {
  float scale = 1.0f;         // multiplies every velocity; |scale| <= kMaxFlowScale
  Vec3f up = Vec3f::UnitY();  // world up for `downhill` (unit or not; must be non-zero)
};

// What the presets read of the synthesis mesh.
struct SurfaceFlowMesh {
  const Mesh* mesh = nullptr;      // the synthesis mesh, with unit vertex normals
  std::span<const Vec3f> fieldUp;  // per vertex: the orientation field's unit up direction
  float spacing = 1.0f;            // world length of one vertex spacing
};

class SurfaceFlow {
 public:
  // Throws ParameterError("flow", ...) for an unknown preset, key or value (flow_limits.h), a
  // malformed pattern, or a zero or non-finite `up` for downhill; ParameterError("flowScale", ...)
  // for a scale beyond kMaxFlowScale;
  // InputError naming the file for a missing or malformed velocity file (with the line number)
  // or one whose line count differs from `input`'s vertex count (the first or only file is read
  // here), InputError("mesh", ...) for an input mesh without triangles. `target.fieldUp` is read
  // by along-field only; nothing of `input` or `target` is kept.
  static SurfaceFlow parse(const std::string& spec, const Mesh& input, const SurfaceFlowMesh& target,
                           const SurfaceFlowOptions& options = {});
  ~SurfaceFlow();
  SurfaceFlow(SurfaceFlow&&) noexcept;
  SurfaceFlow& operator=(SurfaceFlow&&) noexcept;

  // Checks that frames 0 .. frames - 2 have their files (a pattern): each exists, parses and
  // has the input's vertex count. Throws InputError naming the first bad file.
  void requireFrames(int frames) const;

  // Per vertex of the synthesis mesh: the tangent velocity of frame `frame` (world units per
  // frame). Deterministic.
  std::vector<Vec3f> velocities(int frame) const;

  bool timeVarying() const;
  std::string description() const;

 private:
  SurfaceFlow();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace texsynth
