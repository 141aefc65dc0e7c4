#pragma once
// Orientation field for synthesis on mesh surfaces: one unit tangent direction per vertex that
// orients the vertex's resampled neighbourhood (Turk 2001, Wei & Levoy 2001, followed by surface
// synthesis by discrete optimization). The field is the smoothest one under the discrete
// Levi-Civita connection that still follows a guide (Knöppel et al. 2013, "Globally optimal
// direction fields", with an alignment term). Per connected component it minimizes
//   E(u) = sum over edges ab of w_ab |u_b - r_ab u_a|^2 + alignment * sum over v of M_v |q_v| |u_v - q_v / |q_v||^2
// over complex tangent coordinates u, i.e. solves (L + alignment M |Q|) u = alignment M q: L the
// connection Laplacian (cotan weights clamped positive; r_ab the transport from a's tangent plane
// to b's, the rotation taking one vertex normal to the other), M the lumped vertex areas (the
// whole mesh's area scaled to 1), q_v the guide's projection onto v's tangent plane. Weighting
// the pull towards the guide's direction by |q| (rather than pulling u towards q itself) lets
// smoothness alone decide where the projection vanishes: poles get one clean singularity, and a
// large region normal to the guide (a flat top, zero-confidence guides) gets a smooth fill-in
// instead of a field decaying to zero, whose direction would be round-off. The result is u
// normalized. Solved by conjugate gradients preconditioned with an aggregation multigrid built
// on the same connection (Eigen's sparse LDLT at its coarsest level).
#include <span>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/field/rotation_field.h"

namespace texsynth {

struct TangentFieldOptions {
  // World direction the field follows where it is not normal to the surface ("up" for the CGAL
  // meshes). Finite and non-zero; only its direction matters. Ignored by the per-vertex-guide
  // overloads.
  Vec3f guide = Vec3f::UnitY();
  // Weight of the guide against smoothness, in (0, 1e8]. With the mesh's area scaled to 1 the
  // field follows the guide on features larger than about 1 / sqrt(alignment) of the mesh's size
  // and smooths over smaller ones; the same value means the same on every level of a mesh
  // hierarchy. Measured on the CGAL bunny, elephant, cow and armadillo retiled to 48K vertices
  // (mean angle to the guide where the surface is steep / singular triangles / mean turn per
  // edge): 1000 gives 5.3-7.9 degrees / 10-37 / 1.7-2.5 degrees, 3000 gives 3.5-5.7 / 12-36 /
  // 2.0-2.7, 10000 gives 2.0-4.0 / 20-41 / 2.3-2.9 (the field starts following bumps).
  float alignment = 3000.0f;
};

// Throws ParameterError("guide" / "alignment", ...) naming the first bad option.
void validateTangentFieldOptions(const TangentFieldOptions& options);

// One unit tangent per vertex (perpendicular to the vertex normal; normals are computed
// area-weighted where the mesh has none, or a zero or non-finite one), a smooth direction field
// following the tangent projection of options.guide. Where the guide is normal to the surface
// (poles) smoothness alone decides; a component whose every tangent plane is normal to the guide
// gets its smoothest field (the least eigenvector of L u = lambda M u). Open meshes and several
// components are fine; vertices in no triangle get an arbitrary unit tangent of their normal.
// Deterministic for any thread count. Throws InputError("mesh", ...) for a mesh without
// triangles, with bad indices or non-finite coordinates, or of zero area; ParameterError for bad
// options.
std::vector<Vec3f> smoothTangentField(const Mesh& mesh, const TangentFieldOptions& options = {});

// The same solve with a per-vertex guide: world vectors whose length is the confidence, projected
// onto each tangent plane (a zero vector lets smoothness decide there). Throws
// ParameterError("guides", ...) unless there is one finite guide per vertex.
std::vector<Vec3f> smoothTangentField(const Mesh& mesh, std::span<const Vec3f> guides,
                                      const TangentFieldOptions& options = {});

// The tangent projection of a rotation field: each vertex's guide is the field's local x axis at
// the vertex (RotationField::frame(p).x), projected onto the tangent plane and smoothed as above,
// so the few vertices where that axis is nearly normal get a smooth fill-in instead of a jump.
// Throws ParameterError("field", ...) for a field without rotations.
std::vector<Vec3f> tangentFieldFromRotations(const Mesh& mesh, const RotationField& field,
                                             const TangentFieldOptions& options = {});

}  // namespace texsynth
