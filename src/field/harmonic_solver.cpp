#include "texsynth/field/harmonic_solver.h"

#include <Eigen/Cholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {

namespace {

using Sparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using Triplet = Eigen::Triplet<double>;
template <typename Scalar>
using SparseOf = Eigen::SparseMatrix<Scalar, Eigen::RowMajor>;
template <typename Scalar>
using ValuesOf = Eigen::Matrix<Scalar, Eigen::Dynamic, 4, Eigen::RowMajor>;
// The multigrid cycle runs in single precision: it only preconditions, and halving the memory traffic
// of its sweeps is most of the solve's time; CG itself stays in double.
using Smoothing = float;
using SmoothValues = ValuesOf<Smoothing>;

// Rows per chunk of parallel work: fixed, so sums never depend on the thread count.
constexpr std::int64_t kChunk = 4096;
// Below this many nodes the coarsest level is solved directly (dense LDLT).
constexpr std::int64_t kCoarsestNodes = 400;
// Gauss-Seidel sweeps before and after each coarse correction.
constexpr int kSweeps = 1;

// Eq. 1 on the grid: row i is q_i - sum_j q_j / d_i over the 6-neighbourhood.
Sparse gridLaplacian(const FieldGrid& grid) {
  std::vector<Triplet> entries;
  entries.reserve(std::size_t(grid.nodeCount()) * 7);
  const Vec3i n = grid.nodes;
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i) {
        const std::int64_t row = grid.index(i, j, k);
        std::int64_t neighbours[6];
        int degree = 0;
        if (i > 0) neighbours[degree++] = grid.index(i - 1, j, k);
        if (i + 1 < n.x()) neighbours[degree++] = grid.index(i + 1, j, k);
        if (j > 0) neighbours[degree++] = grid.index(i, j - 1, k);
        if (j + 1 < n.y()) neighbours[degree++] = grid.index(i, j + 1, k);
        if (k > 0) neighbours[degree++] = grid.index(i, j, k - 1);
        if (k + 1 < n.z()) neighbours[degree++] = grid.index(i, j, k + 1);
        entries.emplace_back(row, row, 1.0);
        for (int d = 0; d < degree; ++d) entries.emplace_back(row, neighbours[d], -1.0 / degree);
      }
  Sparse laplacian(grid.nodeCount(), grid.nodeCount());
  laplacian.setFromTriplets(entries.begin(), entries.end());
  return laplacian;
}

// Trilinear prolongation from coarserGrid(fine) to fine: a tensor product of 1D weights.
Sparse prolongation(const FieldGrid& fine, const FieldGrid& coarse) {
  auto weights1d = [](int i) {
    std::vector<std::pair<int, double>> w;
    if (i % 2 == 0) {
      w.push_back({i / 2, 1.0});
    } else {
      w.push_back({i / 2, 0.5});
      w.push_back({i / 2 + 1, 0.5});
    }
    return w;
  };
  std::vector<Triplet> entries;
  entries.reserve(std::size_t(fine.nodeCount()) * 8);
  for (int k = 0; k < fine.nodes.z(); ++k)
    for (int j = 0; j < fine.nodes.y(); ++j)
      for (int i = 0; i < fine.nodes.x(); ++i)
        for (auto [ck, wk] : weights1d(k))
          for (auto [cj, wj] : weights1d(j))
            for (auto [ci, wi] : weights1d(i))
              entries.emplace_back(fine.index(i, j, k), coarse.index(ci, cj, ck), wi * wj * wk);
  Sparse p(fine.nodeCount(), coarse.nodeCount());
  p.setFromTriplets(entries.begin(), entries.end());
  return p;
}

// y = A x, rows in parallel (each row independent, so deterministic).
template <typename Scalar>
void multiply(const SparseOf<Scalar>& a, const ValuesOf<Scalar>& x, ValuesOf<Scalar>& y) {
  y.resize(a.rows(), 4);
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const Scalar* value = a.valuePtr();
  parallelForChunks(0, a.rows(), kChunk, [&](std::int64_t begin, std::int64_t end) {
    const Scalar* xs = x.data();
    Scalar* ys = y.data();
    for (std::int64_t i = begin; i < end; ++i) {
      Scalar s0 = 0, s1 = 0, s2 = 0, s3 = 0;
      for (int e = outer[i]; e < outer[i + 1]; ++e) {
        const Scalar v = value[e], *xj = xs + 4 * std::int64_t(inner[e]);
        s0 += v * xj[0], s1 += v * xj[1], s2 += v * xj[2], s3 += v * xj[3];
      }
      Scalar* yi = ys + 4 * i;
      yi[0] = s0, yi[1] = s1, yi[2] = s2, yi[3] = s3;
    }
  });
}

// Column-wise dot products, summed per fixed chunk and then in chunk order.
Eigen::Vector4d columnDots(const FieldValues& a, const FieldValues& b) {
  const std::int64_t rows = a.rows(), chunks = (rows + kChunk - 1) / kChunk;
  std::vector<Eigen::Vector4d> partial(std::size_t(chunks), Eigen::Vector4d::Zero());
  // One task per fixed chunk (TBB's own ranges are not aligned to the grain).
  parallelFor(0, chunks, [&](std::int64_t chunk) {
    Eigen::Vector4d sum = Eigen::Vector4d::Zero();
    const std::int64_t end = std::min(rows, (chunk + 1) * kChunk);
    for (std::int64_t i = chunk * kChunk; i < end; ++i) sum += a.row(i).cwiseProduct(b.row(i)).transpose();
    partial[std::size_t(chunk)] = sum;
  });
  Eigen::Vector4d total = Eigen::Vector4d::Zero();
  for (const auto& p : partial) total += p;
  return total;
}

// One Gauss-Seidel sweep on A x = b, forwards or backwards (a symmetric pair keeps the
// cycle symmetric, as conjugate gradients needs).
template <typename Scalar>
void gaussSeidel(const SparseOf<Scalar>& a, const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& inverseDiagonal,
                 const ValuesOf<Scalar>& b, ValuesOf<Scalar>& x, bool forward) {
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const Scalar* value = a.valuePtr();
  const std::int64_t n = a.rows();
  Scalar* xs = x.data();
  const Scalar* bs = b.data();
  for (std::int64_t step = 0; step < n; ++step) {
    const std::int64_t i = forward ? step : n - 1 - step;
    // The diagonal term is included in the sum and added back: no branch in the inner loop.
    Scalar* xi = xs + 4 * i;
    Scalar s0 = bs[4 * i], s1 = bs[4 * i + 1], s2 = bs[4 * i + 2], s3 = bs[4 * i + 3];
    for (int e = outer[i]; e < outer[i + 1]; ++e) {
      const Scalar v = value[e], *xj = xs + 4 * std::int64_t(inner[e]);
      s0 -= v * xj[0], s1 -= v * xj[1], s2 -= v * xj[2], s3 -= v * xj[3];
    }
    const Scalar inv = inverseDiagonal[i], d = Scalar(1) / inv;
    xi[0] = (s0 + d * xi[0]) * inv, xi[1] = (s1 + d * xi[1]) * inv;
    xi[2] = (s2 + d * xi[2]) * inv, xi[3] = (s3 + d * xi[3]) * inv;
  }
}

}  // namespace

void validateHarmonicSolverOptions(const HarmonicSolverOptions& options) {
  if (!(options.weight >= kMinConstraintWeight && options.weight <= kMaxConstraintWeight))
    throw ParameterError("weight", "must be in [1, 10000] (the paper uses 100), got " + std::to_string(options.weight));
  if (!(options.tolerance > 0 && options.tolerance <= 0.1)) throw ParameterError("tolerance", "must be in (0, 0.1]");
  if (options.maxIterations < 1) throw ParameterError("maxIterations", "must be at least 1");
}

struct HarmonicSolver::Impl {
  struct Level {
    FieldGrid grid;
    Sparse smooth;      // Galerkin projection of L^T L
    Sparse constraint;  // Galerkin projection of w^2 S
    Sparse system;      // smooth + constraint
    Eigen::VectorXd inverseDiagonal;
    Sparse toFiner;  // prolongation to the previous (finer) level; empty on level 0
    // Single-precision copies for the multigrid cycle.
    SparseOf<Smoothing> systemF, toFinerF, toCoarserF;
    Eigen::Matrix<Smoothing, Eigen::Dynamic, 1> inverseDiagonalF;
  };
  HarmonicSolverOptions options;
  std::vector<Level> levels;
  std::map<std::int64_t, Eigen::Vector4d> constraints;
  bool dirty = true;
  Eigen::LDLT<Eigen::MatrixXd> coarsest;
  // The finest level applies L^T L as L then L^T (7 entries per row twice instead of 25).
  Sparse laplacian, laplacianT;
  SparseOf<Smoothing> laplacianF, laplacianTF;
  std::vector<std::pair<std::int64_t, double>> penalties;  // w^2 at constrained nodes

  mutable SmoothValues finestProductF;
  mutable FieldValues finestProductD;
  template <typename Scalar>
  ValuesOf<Scalar>& finestProduct() const {
    if constexpr (std::is_same_v<Scalar, Smoothing>)
      return finestProductF;
    else
      return finestProductD;
  }

  // y = (L^T L + w^2 S) x on the finest level.
  template <typename Scalar>
  void applyFinest(const SparseOf<Scalar>& l, const SparseOf<Scalar>& lt, const ValuesOf<Scalar>& x,
                   ValuesOf<Scalar>& y) const {
    ValuesOf<Scalar>& lx = finestProduct<Scalar>();  // reused: no allocation per product
    multiply(l, x, lx);
    multiply(lt, lx, y);
    for (const auto& [node, penalty] : penalties) y.row(node) += Scalar(penalty) * x.row(node);
  }

  void build(const FieldGrid& grid) {
    laplacian = gridLaplacian(grid);
    laplacianT = laplacian.transpose();
    laplacianF = laplacian.cast<Smoothing>();
    laplacianTF = laplacianT.cast<Smoothing>();
    Level finest;
    finest.grid = grid;
    finest.smooth = Sparse(laplacian.transpose()) * laplacian;
    levels.push_back(std::move(finest));
    while (levels.back().grid.nodeCount() > kCoarsestNodes) {
      const Level& fine = levels.back();
      Level coarse;
      coarse.grid = coarserGrid(fine.grid);
      coarse.toFiner = prolongation(fine.grid, coarse.grid);
      Sparse restriction = coarse.toFiner.transpose();
      coarse.smooth = restriction * fine.smooth * coarse.toFiner;
      levels.push_back(std::move(coarse));
    }
  }

  // Rebuilds the constraint terms and system matrices of every level after constraints changed.
  void assemble() {
    const double w2 = options.weight * options.weight;
    Sparse diagonal(levels[0].grid.nodeCount(), levels[0].grid.nodeCount());
    std::vector<Triplet> entries;
    penalties.clear();
    for (const auto& [node, target] : constraints)
      entries.emplace_back(node, node, w2), penalties.push_back({node, w2});
    diagonal.setFromTriplets(entries.begin(), entries.end());
    levels[0].constraint = diagonal;
    for (std::size_t l = 1; l < levels.size(); ++l) {
      Sparse restriction = levels[l].toFiner.transpose();
      levels[l].constraint = restriction * levels[l - 1].constraint * levels[l].toFiner;
    }
    for (Level& level : levels) {
      level.system = level.smooth + level.constraint;
      level.inverseDiagonal = level.system.diagonal().cwiseInverse();
      level.systemF = level.system.cast<Smoothing>();
      level.inverseDiagonalF = level.inverseDiagonal.cast<Smoothing>();
      if (level.toFiner.rows() > 0) {
        level.toFinerF = level.toFiner.cast<Smoothing>();
        level.toCoarserF = SparseOf<Smoothing>(level.toFinerF.transpose());
      }
    }
    coarsest.compute(Eigen::MatrixXd(levels.back().system));
    dirty = false;
  }

  // Per level, the buffers one visit of the W-cycle works in: reused across cycles and CG
  // iterations, so a solve allocates (and page-faults) nothing after its first cycle.
  struct CycleScratch {
    SmoothValues product, residual, coarseResidual, coarseError, coarseProduct, second, correction;
  };
  mutable std::vector<CycleScratch> scratch;
  mutable SmoothValues cycleInput, cycleOutput;

  // One W-cycle: an approximate inverse of the level's system applied to r.
  void wCycle(std::size_t l, const SmoothValues& r, SmoothValues& e) const {
    const Level& level = levels[l];
    if (l + 1 == levels.size()) {
      e = coarsest.solve(r.cast<double>()).cast<Smoothing>();
      return;
    }
    CycleScratch& s = scratch[l];
    e.setZero(r.rows(), 4);
    for (int k = 0; k < kSweeps; ++k) gaussSeidel(level.systemF, level.inverseDiagonalF, r, e, true);
    if (l == 0)
      applyFinest(laplacianF, laplacianTF, e, s.product);
    else
      multiply(level.systemF, e, s.product);
    const Level& coarse = levels[l + 1];
    s.residual = r - s.product;
    multiply(coarse.toCoarserF, s.residual, s.coarseResidual);
    wCycle(l + 1, s.coarseResidual, s.coarseError);
    // A second visit of the coarse level (a W-cycle): the linear interpolation is weak for a
    // fourth-order operator, and coarse work is cheap; this saves about a third of the CG
    // iterations. Two symmetric visits keep the preconditioner symmetric.
    if (l + 2 < levels.size()) {
      multiply(coarse.systemF, s.coarseError, s.coarseProduct);
      s.coarseProduct = s.coarseResidual - s.coarseProduct;
      wCycle(l + 1, s.coarseProduct, s.second);
      s.coarseError += s.second;
    }
    multiply(coarse.toFinerF, s.coarseError, s.correction);
    e += s.correction;
    for (int k = 0; k < kSweeps; ++k) gaussSeidel(level.systemF, level.inverseDiagonalF, r, e, false);
  }

  // The preconditioner on a double-precision residual.
  void precondition(const FieldValues& r, FieldValues& z) const {
    scratch.resize(levels.size());
    cycleInput = r.cast<Smoothing>();
    wCycle(0, cycleInput, cycleOutput);
    z = cycleOutput.cast<double>();
  }

  HarmonicSolveStats solve(FieldValues& x) {
    auto start = std::chrono::steady_clock::now();
    if (constraints.empty()) throw ParameterError("constraints", "at least one node must be constrained");
    if (dirty) assemble();
    const Level& top = levels[0];
    const std::int64_t n = top.grid.nodeCount();
    FieldValues b = FieldValues::Zero(n, 4);
    const double w2 = options.weight * options.weight;
    for (const auto& [node, target] : constraints) b.row(node) = w2 * target.transpose();
    if (x.rows() != n) x.setZero(n, 4);

    HarmonicSolveStats stats;
    const double bNorm = std::sqrt(columnDots(b, b).sum());
    FieldValues r, z, p, ap;
    applyFinest(laplacian, laplacianT, x, ap);
    r = b - ap;
    auto relative = [&] { return std::sqrt(columnDots(r, r).sum()) / bNorm; };
    stats.relativeResidual = relative();
    // Already solved (an unchanged problem): nothing to do.
    if (stats.relativeResidual > 1e-14) {
      precondition(r, z);
      p = z;
      Eigen::Vector4d rz = columnDots(r, z);
      for (int it = 1; it <= options.maxIterations; ++it) {
        applyFinest(laplacian, laplacianT, p, ap);
        Eigen::Vector4d pap = columnDots(p, ap), alpha;
        // A column already solved (all zero) has zero curvature: leave it alone.
        for (int c = 0; c < 4; ++c) alpha[c] = pap[c] > 0 ? rz[c] / pap[c] : 0.0;
        x += p * alpha.asDiagonal();  // coefficient-wise, no temporary
        r -= ap * alpha.asDiagonal();
        stats.iterations = it;
        stats.relativeResidual = relative();
        // The residual is dominated by the w^2-weighted constraint rows, so it says little about
        // the smooth part of the field; stop on the size of the step instead (values are O(1)).
        stats.relativeStep = (p * alpha.asDiagonal()).cwiseAbs().maxCoeff() / std::max(1e-300, x.cwiseAbs().maxCoeff());
        if (stats.relativeStep <= options.tolerance) break;
        precondition(r, z);
        Eigen::Vector4d rzNew = columnDots(r, z), beta;
        for (int c = 0; c < 4; ++c) beta[c] = rz[c] > 0 ? rzNew[c] / rz[c] : 0.0;
        rz = rzNew;
        p = z + p * beta.asDiagonal();
      }
    }
    stats.converged = stats.relativeStep <= options.tolerance || stats.relativeResidual <= 1e-14;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
  }
};

HarmonicSolver::HarmonicSolver(const FieldGrid& grid, const HarmonicSolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  validateHarmonicSolverOptions(options);
  impl_->options = options;
  impl_->build(grid);
}
HarmonicSolver::~HarmonicSolver() = default;
HarmonicSolver::HarmonicSolver(HarmonicSolver&&) noexcept = default;
HarmonicSolver& HarmonicSolver::operator=(HarmonicSolver&&) noexcept = default;

const FieldGrid& HarmonicSolver::grid() const {
  return impl_->levels[0].grid;
}

void HarmonicSolver::setConstraint(std::int64_t node, const Eigen::Vector4d& target) {
  if (node < 0 || node >= grid().nodeCount()) throw ParameterError("node", "outside the grid");
  if (!target.allFinite()) throw ParameterError("target", "must be finite");
  auto [it, inserted] = impl_->constraints.insert_or_assign(node, target);
  (void)it;
  // A new constrained node changes the matrix; a new target only the right-hand side.
  if (inserted) impl_->dirty = true;
}

void HarmonicSolver::clearConstraints() {
  impl_->constraints.clear();
  impl_->dirty = true;
}

const std::map<std::int64_t, Eigen::Vector4d>& HarmonicSolver::constraints() const {
  return impl_->constraints;
}

HarmonicSolveStats HarmonicSolver::solve(FieldValues& values) {
  return impl_->solve(values);
}

}  // namespace texsynth
