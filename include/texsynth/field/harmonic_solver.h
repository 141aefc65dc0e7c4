#pragma once
// Harmonic interpolation on a field grid (sketch-guided solid texturing eq. 2): minimizes
//   ||L X||^2 + w^2 * sum over constrained nodes v of ||X(v) - target(v)||^2
// for up to four independent components at once (the quaternion's w, x, y, z), where L is the
// grid Laplacian with 1-ring (6-neighbour) weights 1/d_i. The normal equations
// (L^T L + w^2 S) X = w^2 S T are solved by conjugate gradients preconditioned with a Galerkin
// multigrid W-cycle. Only the diagonal term S changes when constraints are added, so the
// hierarchy of L^T L is built once and each update warm-starts from the previous solution.
// (A sparse Cholesky factorization, reusable across updates, is no option in 3D: L^T L fills in
// so badly that Eigen's SimplicialLDLT needs over three minutes at 33^3 nodes.)
#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <memory>

#include "texsynth/field/field_grid.h"

namespace texsynth {

// One row per grid node, four components per row.
using FieldValues = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

// The range of w in which the solver works. Below 1 the curves barely pin the field (w = 0.1 leaves
// constrained frames 19 degrees off theirs); w^2 enters the system, and from about 1e6 on it swamps
// the smoothness term in the single-precision multigrid smoothing, so CG stops converging on a
// 24-cell grid and leaves frames up to 180 degrees off (measured on a cube with four curves).
inline constexpr double kMinConstraintWeight = 1, kMaxConstraintWeight = 1e4;

struct HarmonicSolverOptions {
  // w in eq. 2: balances smoothness against the constraints; the paper uses 100. In
  // [kMinConstraintWeight, kMaxConstraintWeight].
  double weight = 100;
  // Stop when a CG step changes no value by more than tolerance * the largest value (the field
  // is then within about 0.002 degrees of the exact minimizer on average at the default); in (0, 0.1].
  double tolerance = 1e-4;
  // Give up (keeping the best iterate) after this many CG iterations; >= 1.
  int maxIterations = 400;
};

// Throws ParameterError naming the first invalid option.
void validateHarmonicSolverOptions(const HarmonicSolverOptions& options);

struct HarmonicSolveStats {
  int iterations = 0;
  double relativeResidual = 0;  // ||b - A x|| / ||b||
  double relativeStep = 0;      // the last step's largest change / the largest value
  double seconds = 0;
  bool converged = false;
};

class HarmonicSolver {
 public:
  // Builds L^T L and its multigrid hierarchy (the part that never changes).
  HarmonicSolver(const FieldGrid& grid, const HarmonicSolverOptions& options = {});
  ~HarmonicSolver();
  HarmonicSolver(HarmonicSolver&&) noexcept;
  HarmonicSolver& operator=(HarmonicSolver&&) noexcept;

  const FieldGrid& grid() const;
  // Sets (or replaces) the target at one node; throws ParameterError("node", ...) if out of range.
  void setConstraint(std::int64_t node, const Eigen::Vector4d& target);
  void clearConstraints();
  const std::map<std::int64_t, Eigen::Vector4d>& constraints() const;

  // Solves for all nodes. `values` is the starting guess when it has one row per node (warm
  // start), otherwise it is reset to zero. Throws ParameterError("constraints", ...) when there
  // are none (the energy would have no unique minimum).
  HarmonicSolveStats solve(FieldValues& values);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace texsynth
