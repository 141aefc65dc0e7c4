#pragma once
// The pieces of SurfaceFlow: the analytic presets and per-vertex velocity files carried from the
// input mesh to the synthesis mesh. Internal to the animation module.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "texsynth/animation/surface_flow.h"
#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/parallel.h"

namespace texsynth::flow_detail {

// Presets: one tangent velocity per vertex of target.mesh, the largest speed |strength| x
// target.spacing (a negative strength reverses the flow).
std::vector<Vec3f> swirlVelocities(const SurfaceFlowMesh& target, float strength, std::uint64_t seed);
std::vector<Vec3f> downhillVelocities(const SurfaceFlowMesh& target, const Vec3f& up, float strength);
std::vector<Vec3f> alongFieldVelocities(const SurfaceFlowMesh& target, float strength);

// A per-vertex velocity file: "vx vy vz" per line, '#' comments and blank lines skipped. Throws
// InputError naming `path` (with the line number for a malformed line) when it is missing,
// malformed or has other than `vertexCount` lines.
std::vector<Vec3f> readVertexVelocities(const std::string& path, std::size_t vertexCount);

// Carries per-vertex velocities of an input mesh to a target mesh's vertices: each takes the
// barycentric blend at its closest point on the input, projected onto its tangent plane.
class VertexTransfer {
 public:
  // Throws InputError("mesh", ...) for an input without triangles.
  VertexTransfer(const Mesh& input, const Mesh& target);
  std::vector<Vec3f> tangentVelocities(std::span<const Vec3f> inputVelocities) const;

 private:
  std::vector<Vec3i> corners_;
  std::vector<Vec3f> weights_, normals_;
};

// velocity(vertex) for every vertex, computed in parallel chunks (the same for any thread count).
template <class Velocity>
std::vector<Vec3f> perVertex(std::size_t vertexCount, const Velocity& velocity) {
  std::vector<Vec3f> out(vertexCount);
  parallelForChunks(0, std::int64_t(vertexCount), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) out[std::size_t(v)] = velocity(std::size_t(v));
  });
  return out;
}

}  // namespace texsynth::flow_detail
