// Smooth tangent direction fields on meshes (see tangent_field.h): the connection Laplacian of
// the mesh with a guide-alignment term, solved per connected component by conjugate gradients
// with an aggregation multigrid preconditioner.
#include "texsynth/surface/tangent_field.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <functional>
#include <numeric>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/geometry/cotangent_weights.h"

namespace texsynth {

namespace {

using Complex = std::complex<double>;
using Vector = std::vector<Complex>;
using Vec3d = Eigen::Vector3d;

constexpr float kMaxAlignment = 1e8f;
// Cotangents are clamped to this magnitude (near-degenerate triangles) and edge weights kept at
// least kMinWeight, so the Laplacian stays positive and every edge keeps its vertices coupled.
constexpr double kMaxCotangent = 1e3;
constexpr double kMinWeight = 1e-2;
// Vertex masses (the mesh's area scaled to 1) are at least this over the vertex count, so a
// vertex or a component whose triangles all have zero area still gets a solvable system.
constexpr double kMinMass = 1e-9;
// A guide within about 0.006 degrees of the normal (relative projection below this) counts as
// normal: float noise in the normals must not decide a direction there.
constexpr double kNormalGuideTolerance = 1e-4;
// Conjugate gradients stop at this relative residual: directions within 0.1 degrees of the exact
// solution (mean 0.0005, measured on retiled meshes) except at a vertex on a singularity, where
// the direction is undefined.
constexpr double kTolerance = 1e-5;
constexpr int kMaxIterations = 2000;
// Multigrid levels stop at this many unknowns, solved by sparse LDLT.
constexpr int kCoarsest = 1500;
// Inverse iteration for the smoothest field of a component no guide reaches: at most this many
// steps, stopping when 1 - cos(angle between steps) falls below the tolerance; the shift keeps
// L + shift M definite (relative to the component's mass).
constexpr int kInverseIterations = 20;
constexpr double kInverseTolerance = 1e-10;
constexpr double kSmoothestShift = 1e-6;
// Rows per chunk of the parallel loops: fixed, so sums do not depend on the thread count.
constexpr int kChunk = 4096;

// ---------------------------------------------------------------------------------------------
// Geometry: tangent planes, edges, transport.

// Per-vertex tangent planes: unit normal and an orthonormal reference basis (e1, e2).
struct TangentPlanes {
  std::vector<Vec3d> normal, e1, e2;
};

TangentPlanes tangentPlanes(const Mesh& mesh) {
  const std::size_t n = mesh.vertexCount();
  auto usable = [](const Vec3f& v) { return v.allFinite() && v.squaredNorm() > 1e-20f; };
  Mesh computed;  // area-weighted normals where the mesh has none, or a zero / non-finite one
  if (mesh.normals.empty() || !std::all_of(mesh.normals.begin(), mesh.normals.end(), usable)) {
    computed.positions = mesh.positions;
    computed.triangles = mesh.triangles;
    computed.computeNormals();
  }
  TangentPlanes planes{std::vector<Vec3d>(n), std::vector<Vec3d>(n), std::vector<Vec3d>(n)};
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3f& given = mesh.normals.empty() || !usable(mesh.normals[v]) ? computed.normals[v] : mesh.normals[v];
    const Frame f = Frame::fromNormal(given);
    const Vec3d normal = given.cast<double>().normalized();
    // Orthonormal in double precision.
    const Vec3d e1 = (f.x.cast<double>() - f.x.cast<double>().dot(normal) * normal).normalized();
    planes.normal[v] = normal;
    planes.e1[v] = e1;
    planes.e2[v] = normal.cross(e1);
  }
  return planes;
}

Complex toTangent(const TangentPlanes& planes, std::size_t v, const Vec3d& w) {
  return {w.dot(planes.e1[v]), w.dot(planes.e2[v])};
}

// Rotates w by the smallest rotation taking unit vector `from` to unit vector `to`; for opposite
// vectors, by half a turn about `fold` (a unit vector perpendicular to `from`).
Vec3d rotateBetween(const Vec3d& from, const Vec3d& to, const Vec3d& fold, const Vec3d& w) {
  const double c = from.dot(to);
  const Vec3d axis = from.cross(to);
  if (c > -1 + 1e-9) return c * w + axis.cross(w) + axis * (axis.dot(w) / (1 + c));
  return 2 * fold.dot(w) * fold - w;
}

// Discrete Levi-Civita transport from a's tangent coordinates to b's, a unit complex number: the
// rotation taking a's normal to b's, applied to a's reference direction, measured in b's basis.
Complex transport(const TangentPlanes& planes, const Mesh& mesh, int a, int b) {
  const Vec3d edge = (mesh.positions[std::size_t(b)] - mesh.positions[std::size_t(a)]).cast<double>();
  Vec3d fold = edge - edge.dot(planes.normal[std::size_t(a)]) * planes.normal[std::size_t(a)];
  fold = fold.squaredNorm() > 0 ? Vec3d(fold.normalized()) : planes.e1[std::size_t(a)];
  const Vec3d moved =
      rotateBetween(planes.normal[std::size_t(a)], planes.normal[std::size_t(b)], fold, planes.e1[std::size_t(a)]);
  const Complex r = toTangent(planes, std::size_t(b), moved);
  return r / std::abs(r);
}

// One undirected edge a < b: its cotan weight and the transport from a's coordinates to b's.
struct Edge {
  int a, b;
  double weight;
  Complex transport;
};

// Unique edges sorted by (a, b) with cotan weights summed over their triangles (clamped), and the
// lumped (barycentric) vertex areas.
std::vector<Edge> buildEdges(const Mesh& mesh, const TangentPlanes& planes, std::vector<double>& area) {
  area.assign(mesh.vertexCount(), 0.0);
  for (const Vec3i& t : mesh.triangles) {
    const Vec3d p0 = mesh.positions[std::size_t(t[0])].cast<double>();
    const double doubleArea = (mesh.positions[std::size_t(t[1])].cast<double>() - p0)
                                  .cross(mesh.positions[std::size_t(t[2])].cast<double>() - p0)
                                  .norm();
    for (int k = 0; k < 3; ++k) area[std::size_t(t[k])] += doubleArea / 6;
  }
  std::vector<Edge> edges;
  for (const CotangentEdge& e : cotangentEdges(mesh, kMaxCotangent))
    edges.push_back({e.a, e.b, std::max(e.weight, kMinWeight), {}});
  parallelFor(
      0, std::int64_t(edges.size()),
      [&](std::int64_t i) {
        Edge& e = edges[std::size_t(i)];
        e.transport = transport(planes, mesh, e.a, e.b);
      },
      kChunk);
  return edges;
}

// ---------------------------------------------------------------------------------------------
// Sparse Hermitian matrices and deterministic parallel loops.

// Runs body(first, last) over fixed chunks of [0, count) in parallel and returns the chunks'
// results summed in chunk order: the same bits for any thread count.
double chunkedSum(int count, const std::function<double(int, int)>& body) {
  const int chunks = (count + kChunk - 1) / kChunk;
  if (chunks <= 1) return body(0, count);
  std::vector<double> partial(static_cast<std::size_t>(chunks));
  parallelFor(0, chunks, [&](std::int64_t c) {
    const int first = int(c) * kChunk;
    partial[std::size_t(c)] = body(first, std::min(count, first + kChunk));
  });
  return std::accumulate(partial.begin(), partial.end(), 0.0);
}

void forChunks(int count, const std::function<void(int, int)>& body) {
  chunkedSum(count, [&](int lo, int hi) {
    body(lo, hi);
    return 0.0;
  });
}

// Re <a, b>. The memory-bound loops read complex numbers as (re, im) pairs, which std::complex
// guarantees: copies of std::complex temporaries stall on store forwarding there.
double realDot(const Vector& a, const Vector& b) {
  const double* x = reinterpret_cast<const double*>(a.data());
  const double* y = reinterpret_cast<const double*>(b.data());
  return chunkedSum(int(a.size()), [&](int lo, int hi) {
    double sum = 0;
    for (int i = 2 * lo; i < 2 * hi; ++i) sum += x[i] * y[i];
    return sum;
  });
}

// A Hermitian matrix in compressed rows: the real diagonal apart, then each row's off-diagonals.
struct Matrix {
  int size = 0;
  std::vector<double> diagonal;
  std::vector<std::int64_t> rowStart{0};
  std::vector<int> column;
  Vector value;

  // y = A x; returns Re <x, A x>.
  double multiply(const Vector& x, Vector& y) const {
    const double* a = reinterpret_cast<const double*>(value.data());
    const double* xs = reinterpret_cast<const double*>(x.data());
    double* ys = reinterpret_cast<double*>(y.data());
    return chunkedSum(size, [&](int lo, int hi) {
      double dot = 0;
      for (int i = lo; i < hi; ++i) {
        const double xRe = xs[2 * i], xIm = xs[2 * i + 1], d = diagonal[std::size_t(i)];
        double re = d * xRe, im = d * xIm;
        for (std::int64_t k = rowStart[std::size_t(i)]; k < rowStart[std::size_t(i) + 1]; ++k) {
          const std::int64_t j = 2 * std::int64_t(column[std::size_t(k)]);
          re += a[2 * k] * xs[j] - a[2 * k + 1] * xs[j + 1];
          im += a[2 * k] * xs[j + 1] + a[2 * k + 1] * xs[j];
        }
        ys[2 * i] = re;
        ys[2 * i + 1] = im;
        dot += xRe * re + xIm * im;
      }
      return dot;
    });
  }

  // The lower triangle, as Eigen's SimplicialLDLT reads it.
  Eigen::SparseMatrix<Complex> lowerTriangle() const {
    std::vector<Eigen::Triplet<Complex>> entries;
    for (int i = 0; i < size; ++i) {
      entries.emplace_back(i, i, diagonal[std::size_t(i)]);
      for (std::int64_t k = rowStart[std::size_t(i)]; k < rowStart[std::size_t(i) + 1]; ++k)
        if (column[std::size_t(k)] < i) entries.emplace_back(i, column[std::size_t(k)], value[std::size_t(k)]);
    }
    Eigen::SparseMatrix<Complex> lower(size, size);
    lower.setFromTriplets(entries.begin(), entries.end());
    return lower;
  }
};

// One connected component: its vertices in breadth-first order (neighbours close in memory),
// its connection Laplacian L over them and their masses.
struct Component {
  std::vector<int> vertices;
  Matrix laplacian;
  std::vector<double> mass;
};

// E(u) = sum over edges of w |u_b - r u_a|^2 (r the transport from a to b) is u^H L u with
// L(a, a) and L(b, b) += w, L(b, a) = -w r and L(a, b) = -w conj(r).
std::vector<Component> buildComponents(std::size_t n, const std::vector<Edge>& edges, const std::vector<double>& mass) {
  // Adjacency (neighbour, edge) per vertex.
  std::vector<std::int64_t> start(n + 1, 0);
  for (const Edge& e : edges) ++start[std::size_t(e.a) + 1], ++start[std::size_t(e.b) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::pair<int, int>> adjacent(static_cast<std::size_t>(start[n]));
  std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    adjacent[std::size_t(fill[std::size_t(edges[i].a)]++)] = {edges[i].b, int(i)};
    adjacent[std::size_t(fill[std::size_t(edges[i].b)]++)] = {edges[i].a, int(i)};
  }
  std::vector<Component> components;
  std::vector<int> rank(n, -1);  // index within its component
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (rank[seed] >= 0 || start[seed] == start[seed + 1]) continue;  // done, or in no edge
    Component c;
    rank[seed] = 0;
    c.vertices.push_back(int(seed));
    for (std::size_t head = 0; head < c.vertices.size(); ++head) {
      const std::size_t v = std::size_t(c.vertices[head]);
      for (std::int64_t k = start[v]; k < start[v + 1]; ++k) {
        const int w = adjacent[std::size_t(k)].first;
        if (rank[std::size_t(w)] < 0) rank[std::size_t(w)] = int(c.vertices.size()), c.vertices.push_back(w);
      }
    }
    Matrix& L = c.laplacian;
    L.size = int(c.vertices.size());
    for (int v : c.vertices) {
      double diagonal = 0;
      for (std::int64_t k = start[std::size_t(v)]; k < start[std::size_t(v) + 1]; ++k) {
        const Edge& e = edges[std::size_t(adjacent[std::size_t(k)].second)];
        diagonal += e.weight;
        L.column.push_back(rank[std::size_t(adjacent[std::size_t(k)].first)]);
        L.value.push_back(-e.weight * (v == e.b ? e.transport : std::conj(e.transport)));
      }
      L.diagonal.push_back(diagonal);
      L.rowStart.push_back(std::int64_t(L.column.size()));
      c.mass.push_back(mass[std::size_t(v)]);
    }
    components.push_back(std::move(c));
  }
  return components;
}

// ---------------------------------------------------------------------------------------------
// The solver.

// Aggregation multigrid for a connection Laplacian, the preconditioner of conjugate gradients.
// Each level groups its unknowns into aggregates (a root with its not yet grouped neighbours;
// leftovers join their strongest grouped neighbour); an aggregate's coarse unknown is a locally
// parallel field, phases transported from the root by the matrix's own connection (-A(i, j) /
// |A(i, j)| carries j's coordinates to i's). The coarse matrix P^H A P stays Hermitian and
// diagonally dominant. A V-cycle of damped Jacobi, coarse correction and damped Jacobi, with an
// exact solve at the coarsest level, is symmetric positive definite as conjugate gradients need.
// Measured: 10-30 iterations on retiled meshes at any size (plain Jacobi-preconditioned CG needs
// 150-650 at 40K-250K vertices; a direct LDLT of the whole system takes 0.2-0.9 s at 40K and
// 2.5 s at 150K).
class Multigrid {
 public:
  explicit Multigrid(Matrix fine) {
    levels_.emplace_back();
    levels_.back().A = std::move(fine);
    while (levels_.back().A.size > kCoarsest) {
      const int count = aggregate(levels_.back());
      if (count > levels_.back().A.size * 3 / 4) break;  // coarsening stalls: solve this level exactly
      Matrix coarse = galerkin(levels_.back(), count);
      levels_.emplace_back();
      levels_.back().A = std::move(coarse);
    }
    for (Level& level : levels_) level.t.resize(std::size_t(level.A.size));
    coarsest_.compute(levels_.back().A.lowerTriangle());
    TS_CHECK_MSG(coarsest_.info() == Eigen::Success, "tangent field: coarse factorization failed");
  }

  const Matrix& matrix() const { return levels_.front().A; }
  // z = B r (B the V-cycle, an approximate inverse of the finest matrix).
  void apply(const Vector& r, Vector& z) { cycle(0, r, z); }

 private:
  struct Level {
    Matrix A;
    std::vector<int> aggregate;  // the coarse unknown of each unknown
    Vector phase;                // P(i, aggregate[i]), unit
    std::vector<int> memberStart, members;
    Vector t, coarseResidual, coarseCorrection;  // work space
  };

  static int aggregate(Level& level) {
    const Matrix& A = level.A;
    const std::size_t n = std::size_t(A.size);
    auto transportTo = [&](std::int64_t k) { return -A.value[std::size_t(k)] / std::abs(A.value[std::size_t(k)]); };
    level.aggregate.assign(n, -1);
    level.phase.assign(n, Complex(1));
    int count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      bool free = level.aggregate[i] < 0;
      for (std::int64_t k = A.rowStart[i]; k < A.rowStart[i + 1] && free; ++k)
        free = level.aggregate[std::size_t(A.column[std::size_t(k)])] < 0;
      if (!free) continue;
      level.aggregate[i] = count;
      for (std::int64_t k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
        const std::size_t j = std::size_t(A.column[std::size_t(k)]);
        level.aggregate[j] = count;
        level.phase[j] = std::conj(transportTo(k));  // from the root i to j
      }
      ++count;
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (level.aggregate[i] >= 0) continue;
      std::int64_t best = -1;
      for (std::int64_t k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
        if (level.aggregate[std::size_t(A.column[std::size_t(k)])] >= 0 &&
            (best < 0 || std::abs(A.value[std::size_t(k)]) > std::abs(A.value[std::size_t(best)])))
          best = k;
      if (best < 0) {  // no neighbour at all: an aggregate of its own
        level.aggregate[i] = count++;
        continue;
      }
      const std::size_t j = std::size_t(A.column[std::size_t(best)]);
      level.aggregate[i] = level.aggregate[j];
      level.phase[i] = transportTo(best) * level.phase[j];
    }
    level.memberStart.assign(std::size_t(count) + 1, 0);
    for (int c : level.aggregate) ++level.memberStart[std::size_t(c) + 1];
    std::partial_sum(level.memberStart.begin(), level.memberStart.end(), level.memberStart.begin());
    level.members.resize(n);
    std::vector<int> fill(level.memberStart.begin(), level.memberStart.end() - 1);
    for (std::size_t i = 0; i < n; ++i) level.members[std::size_t(fill[std::size_t(level.aggregate[i])]++)] = int(i);
    level.coarseResidual.resize(std::size_t(count));
    level.coarseCorrection.resize(std::size_t(count));
    return count;
  }

  // P^H A P, row by row with a sparse accumulator.
  static Matrix galerkin(const Level& level, int count) {
    const Matrix& A = level.A;
    Matrix C;
    C.size = count;
    std::vector<int> slot(std::size_t(count), -1);
    for (int c = 0; c < count; ++c) {
      const std::int64_t rowBegin = std::int64_t(C.column.size());
      Complex diagonal = 0;
      for (int m = level.memberStart[std::size_t(c)]; m < level.memberStart[std::size_t(c) + 1]; ++m) {
        const std::size_t i = std::size_t(level.members[std::size_t(m)]);
        const Complex pi = std::conj(level.phase[i]);
        diagonal += A.diagonal[i];
        for (std::int64_t k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
          const std::size_t j = std::size_t(A.column[std::size_t(k)]);
          const int cj = level.aggregate[j];
          const Complex v = pi * A.value[std::size_t(k)] * level.phase[j];
          if (cj == c) {
            diagonal += v;
            continue;
          }
          if (slot[std::size_t(cj)] < 0) {
            slot[std::size_t(cj)] = int(C.column.size());
            C.column.push_back(cj);
            C.value.push_back(0);
          }
          C.value[std::size_t(slot[std::size_t(cj)])] += v;
        }
      }
      for (std::size_t k = std::size_t(rowBegin); k < C.column.size(); ++k) slot[std::size_t(C.column[k])] = -1;
      C.diagonal.push_back(diagonal.real());
      C.rowStart.push_back(std::int64_t(C.column.size()));
    }
    return C;
  }

  void cycle(std::size_t l, const Vector& r, Vector& z) {
    Level& level = levels_[l];
    const Matrix& A = level.A;
    if (l + 1 == levels_.size()) {
      const Eigen::VectorXcd solution = coarsest_.solve(Eigen::Map<const Eigen::VectorXcd>(r.data(), A.size));
      z.assign(solution.data(), solution.data() + A.size);
      return;
    }
    constexpr double kDamping = 2.0 / 3.0;
    forChunks(A.size, [&](int lo, int hi) {
      for (int i = lo; i < hi; ++i) z[std::size_t(i)] = kDamping / A.diagonal[std::size_t(i)] * r[std::size_t(i)];
    });
    A.multiply(z, level.t);
    forChunks(int(level.coarseResidual.size()), [&](int lo, int hi) {
      for (int c = lo; c < hi; ++c) {
        Complex sum = 0;
        for (int m = level.memberStart[std::size_t(c)]; m < level.memberStart[std::size_t(c) + 1]; ++m) {
          const std::size_t i = std::size_t(level.members[std::size_t(m)]);
          sum += std::conj(level.phase[i]) * (r[i] - level.t[i]);
        }
        level.coarseResidual[std::size_t(c)] = sum;
      }
    });
    cycle(l + 1, level.coarseResidual, level.coarseCorrection);
    forChunks(A.size, [&](int lo, int hi) {
      for (int i = lo; i < hi; ++i)
        z[std::size_t(i)] +=
            level.phase[std::size_t(i)] * level.coarseCorrection[std::size_t(level.aggregate[std::size_t(i)])];
    });
    A.multiply(z, level.t);
    forChunks(A.size, [&](int lo, int hi) {
      for (int i = lo; i < hi; ++i)
        z[std::size_t(i)] += kDamping / A.diagonal[std::size_t(i)] * (r[std::size_t(i)] - level.t[std::size_t(i)]);
    });
  }

  std::vector<Level> levels_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Complex>> coarsest_;
};

// Conjugate gradients on A x = b preconditioned by the multigrid V-cycle, from the guess in x,
// down to a relative residual of kTolerance.
void conjugateGradients(Multigrid& multigrid, const Vector& b, Vector& x) {
  const Matrix& A = multigrid.matrix();
  const std::size_t m = std::size_t(A.size);
  Vector r(m), z(m), p(m), q(m);
  A.multiply(x, q);
  for (std::size_t i = 0; i < m; ++i) r[i] = b[i] - q[i];
  const double limit = kTolerance * kTolerance * realDot(b, b);
  if (realDot(r, r) <= limit) return;
  multigrid.apply(r, z);
  p = z;
  double rz = realDot(r, z);
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double pq = A.multiply(p, q);
    TS_CHECK_MSG(pq > 0 && std::isfinite(pq), "tangent field: system not positive definite");
    const double alpha = rz / pq;
    const double rr = chunkedSum(int(m), [&](int lo, int hi) {
      double sum = 0;
      for (int i = lo; i < hi; ++i) {
        x[std::size_t(i)] += alpha * p[std::size_t(i)];
        r[std::size_t(i)] -= alpha * q[std::size_t(i)];
        sum += std::norm(r[std::size_t(i)]);
      }
      return sum;
    });
    if (rr <= limit) break;
    multigrid.apply(r, z);
    const double rzNext = realDot(r, z);
    const double beta = rzNext / rz;
    rz = rzNext;
    forChunks(int(m), [&](int lo, int hi) {
      for (int i = lo; i < hi; ++i) p[std::size_t(i)] = z[std::size_t(i)] + beta * p[std::size_t(i)];
    });
  }
}

// L + diag(shift), shift per unknown.
Matrix shifted(const Component& c, const std::vector<double>& shift) {
  Matrix A = c.laplacian;
  for (std::size_t i = 0; i < A.diagonal.size(); ++i) A.diagonal[i] += shift[i];
  return A;
}

// The smoothest field of a component no guide reaches: the least eigenvector of L u = lambda M u,
// by inverse iteration (rare: a flat part normal to the guide, or a part whose guides all have
// zero confidence). Each step solves (L + epsilon M) y = M x by the same preconditioned
// conjugate gradients, from the guess x / (Rayleigh quotient).
Vector smoothestField(const Component& c) {
  const std::size_t m = c.vertices.size();
  const double componentMass = std::accumulate(c.mass.begin(), c.mass.end(), 0.0);
  std::vector<double> shift(c.mass);
  for (double& s : shift) s *= kSmoothestShift / componentMass;
  Multigrid multigrid(shifted(c, shift));
  Vector x(m, Complex(1)), b(m), ax(m);
  for (int iteration = 0; iteration < kInverseIterations; ++iteration) {
    const double energy = multigrid.matrix().multiply(x, ax);
    double massNorm = 0;
    for (std::size_t i = 0; i < m; ++i) b[i] = c.mass[i] * x[i], massNorm += c.mass[i] * std::norm(x[i]);
    Vector y = x;
    for (Complex& z : y) z *= massNorm / energy;
    conjugateGradients(multigrid, b, y);
    // Converged when the new field is the old one up to a global rotation (and scale).
    Complex overlap = 0;
    double yNorm = 0;
    for (std::size_t i = 0; i < m; ++i) {
      overlap += std::conj(b[i]) * y[i];  // <x, y>_M
      yNorm += c.mass[i] * std::norm(y[i]);
    }
    TS_CHECK_MSG(yNorm > 0 && std::isfinite(yNorm), "tangent field: inverse iteration failed");
    const double scale = 1 / std::sqrt(yNorm);
    for (Complex& z : y) z *= scale;
    x.swap(y);
    if (1 - std::abs(overlap) * scale / std::sqrt(massNorm) < kInverseTolerance) break;
  }
  return x;
}

// One component's tangent coordinates for the guide projections `target` (component order):
// the minimizer of u^H L u + alignment sum_i M_i |q_i| |u_i - q_i / |q_i||^2, which solves
// (L + alignment M |Q|) u = alignment M q.
Vector solveComponent(const Component& c, const Vector& target, double alignment) {
  const std::size_t m = c.vertices.size();
  Vector u;
  if (std::any_of(target.begin(), target.end(), [](const Complex& z) { return z != Complex(0); })) {
    Vector rhs(m);
    std::vector<double> shift(m);
    for (std::size_t i = 0; i < m; ++i) {
      rhs[i] = alignment * c.mass[i] * target[i];
      shift[i] = alignment * c.mass[i] * std::abs(target[i]);
    }
    u = target;  // the first guess
    Multigrid multigrid(shifted(c, shift));
    conjugateGradients(multigrid, rhs, u);
  } else {
    u = smoothestField(c);
  }
  // An exact zero (a singularity on a vertex) takes the transported sum of its neighbours.
  double largest = 0;
  for (const Complex& z : u) largest = std::max(largest, std::abs(z));
  Vector result = u;
  const Matrix& L = c.laplacian;
  for (std::size_t i = 0; i < m; ++i) {
    if (std::abs(u[i]) > 1e-12 * largest) continue;
    Complex sum = 0;  // -L(i, j) u_j = w T(j -> i) u_j
    for (std::int64_t k = L.rowStart[i]; k < L.rowStart[i + 1]; ++k)
      sum -= L.value[std::size_t(k)] * u[std::size_t(L.column[std::size_t(k)])];
    result[i] = std::abs(sum) > 0 ? sum : Complex(1);
  }
  return result;
}

std::vector<Vec3f> solveField(const Mesh& mesh, const std::vector<Vec3d>& guides, float alignment) {
  const std::size_t n = mesh.vertexCount();
  const TangentPlanes planes = tangentPlanes(mesh);
  std::vector<double> mass;
  const std::vector<Edge> edges = buildEdges(mesh, planes, mass);
  const double totalArea = std::accumulate(mass.begin(), mass.end(), 0.0);
  if (!(totalArea > 0) || !std::isfinite(totalArea)) throw InputError("mesh", "every triangle has zero area");
  // Alignment is relative to the whole mesh's area, so it means the same at any scale and
  // resolution (and on every level of a mesh hierarchy).
  for (double& m : mass) m = std::max(m / totalArea, kMinMass / double(n));
  const std::vector<Component> components = buildComponents(n, edges, mass);

  std::vector<Complex> u(n, Complex(1));  // vertices in no triangle keep their reference direction
  parallelFor(0, std::int64_t(components.size()), [&](std::int64_t index) {
    const Component& c = components[std::size_t(index)];
    Vector target(c.vertices.size());
    for (std::size_t i = 0; i < target.size(); ++i) {
      const std::size_t v = std::size_t(c.vertices[i]);
      const Complex q = toTangent(planes, v, guides[v]);
      target[i] = std::abs(q) > kNormalGuideTolerance * guides[v].norm() ? q : Complex(0);
    }
    const Vector solution = solveComponent(c, target, double(alignment));
    for (std::size_t i = 0; i < solution.size(); ++i) u[std::size_t(c.vertices[i])] = solution[i];
  });

  std::vector<Vec3f> field(n);
  parallelFor(
      0, std::int64_t(n),
      [&](std::int64_t v) {
        const std::size_t i = std::size_t(v);
        const Vec3d t = u[i].real() * planes.e1[i] + u[i].imag() * planes.e2[i];
        const Vec3f normal = planes.normal[i].cast<float>();
        const Vec3f f = t.normalized().cast<float>();
        field[i] = (f - f.dot(normal) * normal).normalized();  // tangent in float precision too
      },
      kChunk);
  return field;
}

void validateAlignment(float alignment) {
  if (!std::isfinite(alignment) || alignment <= 0 || alignment > kMaxAlignment)
    throw ParameterError("alignment", "must be in (0, 1e8], got " + std::to_string(alignment));
}

void validateMesh(const Mesh& mesh) {
  if (mesh.triangles.empty()) throw InputError("mesh", "has no triangles");
  mesh.validate("mesh");
}

}  // namespace

void validateTangentFieldOptions(const TangentFieldOptions& options) {
  if (!options.guide.allFinite() || options.guide.squaredNorm() == 0)
    throw ParameterError("guide", "must be a finite, non-zero direction");
  validateAlignment(options.alignment);
}

std::vector<Vec3f> smoothTangentField(const Mesh& mesh, const TangentFieldOptions& options) {
  validateTangentFieldOptions(options);
  validateMesh(mesh);
  const Vec3d guide = options.guide.cast<double>().normalized();
  return solveField(mesh, std::vector<Vec3d>(mesh.vertexCount(), guide), options.alignment);
}

std::vector<Vec3f> smoothTangentField(const Mesh& mesh, std::span<const Vec3f> guides,
                                      const TangentFieldOptions& options) {
  validateAlignment(options.alignment);
  validateMesh(mesh);
  if (guides.size() != mesh.vertexCount())
    throw ParameterError(
        "guides", std::to_string(guides.size()) + " guides for " + std::to_string(mesh.vertexCount()) + " vertices");
  std::vector<Vec3d> converted(guides.size());
  for (std::size_t v = 0; v < guides.size(); ++v) {
    if (!guides[v].allFinite()) throw ParameterError("guides", "guide " + std::to_string(v) + " is not finite");
    converted[v] = guides[v].cast<double>();
  }
  return solveField(mesh, converted, options.alignment);
}

std::vector<Vec3f> tangentFieldFromRotations(const Mesh& mesh, const RotationField& field,
                                             const TangentFieldOptions& options) {
  validateAlignment(options.alignment);
  validateMesh(mesh);
  if (field.rotations().empty() || std::int64_t(field.rotations().size()) != field.grid().nodeCount())
    throw ParameterError("field", "the rotation field has no rotations for its grid");
  std::vector<Vec3f> guides(mesh.vertexCount());
  parallelFor(
      0, std::int64_t(guides.size()),
      [&](std::int64_t v) { guides[std::size_t(v)] = field.frame(mesh.positions[std::size_t(v)]).x; }, 1024);
  return smoothTangentField(mesh, guides, options);
}

}  // namespace texsynth
