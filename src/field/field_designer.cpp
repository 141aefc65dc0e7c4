#include "texsynth/field/field_designer.h"

#include <chrono>
#include <cmath>
#include <map>

#include "texsynth/core/error.h"
#include "texsynth/core/memory_budget.h"

namespace texsynth {

namespace {

// Solver columns hold (w, x, y, z).
Eigen::Vector4d toVector(const Quatf& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}
Quatf toQuaternion(const Eigen::Vector4d& v) {
  return Quatf(float(v[0]), float(v[1]), float(v[2]), float(v[3]));
}
Quatf flippedTowards(const Quatf& q, const Quatf& reference) {
  return q.dot(reference) < 0 ? Quatf(-q.w(), -q.x(), -q.y(), -q.z()) : q;
}

// Normalizes the solution; a (near) zero interpolant takes a neighbour's direction (the
// paper's singularity rule), found by sweeping in index order until every node has one.
std::vector<Quatf> normalizeField(const FieldGrid& grid, const FieldValues& values) {
  const std::int64_t n = grid.nodeCount();
  double largest = 0;
  for (std::int64_t i = 0; i < n; ++i) largest = std::max(largest, values.row(i).norm());
  const double tiny = 1e-9 * std::max(largest, 1e-300);
  std::vector<Quatf> out(static_cast<std::size_t>(n));
  std::vector<char> known(std::size_t(n), 0);
  std::int64_t missing = 0;
  for (std::int64_t i = 0; i < n; ++i) {
    double norm = values.row(i).norm();
    if (norm > tiny) {
      out[std::size_t(i)] = toQuaternion(values.row(i).transpose() / norm);
      known[std::size_t(i)] = 1;
    } else {
      ++missing;
    }
  }
  if (missing == n) return std::vector<Quatf>(std::size_t(n), Quatf::Identity());
  while (missing > 0) {
    std::vector<char> next = known;
    for (std::int64_t i = 0; i < n; ++i) {
      if (known[std::size_t(i)]) continue;
      Vec3i c = grid.coordinates(i);
      for (int a = 0; a < 3 && !next[std::size_t(i)]; ++a)
        for (int d : {-1, 1}) {
          Vec3i m = c;
          m[a] += d;
          if (m[a] < 0 || m[a] >= grid.nodes[a]) continue;
          std::int64_t j = grid.index(m.x(), m.y(), m.z());
          if (!known[std::size_t(j)]) continue;
          out[std::size_t(i)] = out[std::size_t(j)];
          next[std::size_t(i)] = 1;
          --missing;
          break;
        }
    }
    known = std::move(next);
  }
  return out;
}

// Peak memory per grid node while designing: the solver's matrices and multigrid levels plus the
// fields. Measured on the bunny at --grid 60 and 90 (0.36M and 1.19M nodes, 0.87 and 2.53 GB
// peak): about 2 KB a node; rounded up so the estimate errs on the safe side.
constexpr double kDesignBytesPerNode = 2300;

// The grid, once the memory to design a field on it is known to be there.
FieldGrid designGrid(const Box3f& box, const FieldGridOptions& options) {
  FieldGrid grid = makeFieldGrid(box, options);
  requireMemory(double(grid.nodeCount()) * kDesignBytesPerNode, "shortestCells",
                "a field on " + std::to_string(grid.nodeCount()) + " grid nodes");
  return grid;
}

}  // namespace

void validateFieldDesignOptions(const FieldDesignOptions& options) {
  validateFieldGridOptions(options.grid);
  validateHarmonicSolverOptions(options.solver);
  if (!(options.snapTolerance > 0 && options.snapTolerance <= 1))
    throw ParameterError("snapTolerance", "must be in (0, 1]");
  if (!(options.sampleSpacing > 0 && options.sampleSpacing <= 1))
    throw ParameterError("sampleSpacing", "must be in (0, 1]");
}

struct FieldDesigner::Impl {
  FieldDesignOptions options;
  SurfaceProjector projector;
  FieldGrid grid;
  HarmonicSolver solver;
  FieldValues values;
  RotationField field;
  bool hasField = false;
  float tolerance = 0;
  std::vector<std::vector<CurveSample>> samples;

  Impl(const Mesh& mesh, const FieldDesignOptions& o)
      : options(o),
        projector(mesh),
        grid(designGrid(mesh.bounds(), o.grid)),
        solver(grid, o.solver),
        field(grid),
        tolerance(o.snapTolerance * mesh.bounds().size().norm()) {}

  // Signs (paper §3), per-node averaging, constraints, warm-started solve.
  CurveUpdate constrain(const std::vector<Vec3f>& positions, std::vector<Quatf> rotations, CurveUpdate update) {
    for (std::size_t s = 0; s < rotations.size(); ++s) {
      if (hasField)
        rotations[s] = flippedTowards(rotations[s], field.sample(positions[s]));
      else if (s == 0)
        rotations[s] = flippedTowards(rotations[s], Quatf::Identity());  // w >= 0
      else
        rotations[s] = flippedTowards(rotations[s], rotations[s - 1]);
    }
    // Samples sharing a node are averaged after aligning them with the node's first sample, so
    // opposite signs never cancel; the average then takes the sign closest to the field.
    std::map<std::int64_t, Eigen::Vector4d> perNode;
    for (std::size_t s = 0; s < rotations.size(); ++s) {
      auto [it, inserted] = perNode.try_emplace(grid.nearestNode(positions[s]), toVector(rotations[s]));
      if (!inserted) {
        Eigen::Vector4d v = toVector(rotations[s]);
        it->second += it->second.dot(v) < 0 ? Eigen::Vector4d(-v) : v;
      }
    }
    for (auto& [node, sum] : perNode) {
      Eigen::Vector4d target = sum.normalized();
      if (hasField && target.dot(toVector(field.at(node))) < 0) target = -target;
      solver.setConstraint(node, target);
    }
    update.samples = int(rotations.size());
    update.constrainedNodes = int(perNode.size());
    update.solve = solver.solve(values);
    field = RotationField(grid, normalizeField(grid, values));
    hasField = true;
    return update;
  }
};

FieldDesigner::FieldDesigner(const Mesh& mesh, const FieldDesignOptions& options) {
  validateFieldDesignOptions(options);
  impl_ = std::make_unique<Impl>(mesh, options);
}
FieldDesigner::~FieldDesigner() = default;
FieldDesigner::FieldDesigner(FieldDesigner&&) noexcept = default;
FieldDesigner& FieldDesigner::operator=(FieldDesigner&&) noexcept = default;

const FieldGrid& FieldDesigner::grid() const {
  return impl_->grid;
}
const RotationField& FieldDesigner::field() const {
  return impl_->field;
}
bool FieldDesigner::hasField() const {
  return impl_->hasField;
}
const std::vector<std::vector<CurveSample>>& FieldDesigner::curveSamples() const {
  return impl_->samples;
}

std::vector<std::pair<std::int64_t, Quatf>> FieldDesigner::constraints() const {
  std::vector<std::pair<std::int64_t, Quatf>> out;
  for (const auto& [node, target] : impl_->solver.constraints()) out.push_back({node, toQuaternion(target)});
  return out;
}

CurveUpdate FieldDesigner::addCurve(const SketchCurve& curve, const std::string& source) {
  auto start = std::chrono::steady_clock::now();
  Impl& m = *impl_;
  std::vector<CurveSample> samples =
      sampleCurve(curve, &m.projector, m.options.sampleSpacing * m.grid.spacing, m.tolerance, source);
  const std::string where = curve.name.empty() ? std::string("curve") : "curve '" + curve.name + "'";
  std::vector<Vec3f> positions;
  for (const CurveSample& s : samples) {
    if (!m.grid.contains(s.position)) throw InputError(source, where + " leaves the field's grid");
    positions.push_back(s.position);
  }
  std::vector<Quatf> rotations(samples.size());
  std::vector<Quatf> current(samples.size());
  if (m.hasField)
    for (std::size_t s = 0; s < samples.size(); ++s) current[s] = m.field.sample(samples[s].position);
  CurveUpdate update;
  if (curve.mode == CurveMode::Frame) {
    std::vector<AxisAssignment> choices = allowedAssignments(curve);
    // First curve: the canonical assignment. Later: the one closest to the current field.
    double bestScore = -1;
    for (const AxisAssignment& a : choices) {
      if (!m.hasField) {
        update.assignment = a;
        break;
      }
      double score = 0;
      for (std::size_t s = 0; s < samples.size(); ++s) score += std::abs(frameRotation(samples[s], a).dot(current[s]));
      if (score > bestScore + 1e-9) bestScore = score, update.assignment = a;
    }
    for (std::size_t s = 0; s < samples.size(); ++s) rotations[s] = frameRotation(samples[s], update.assignment);
  } else {
    if (!m.hasField)
      throw InputError(source, where +
                                   " has \"mode\": \"align\" but there is no field to refine yet; the first "
                                   "curve must be a \"frame\" curve");
    // The one axis of six (+-x, +-y, +-z) that best matches the tangents along the whole curve.
    double bestScore = -1e300;
    for (int axis = 0; axis < 3; ++axis) {
      if (curve.tangentAxis && axis != *curve.tangentAxis) continue;
      for (bool flip : {false, true}) {
        double score = 0;
        for (std::size_t s = 0; s < samples.size(); ++s) {
          Vec3f d = current[s].toRotationMatrix().col(axis);
          score += (flip ? -1.0 : 1.0) * double(d.dot(samples[s].tangent));
        }
        if (score > bestScore + 1e-9) bestScore = score, update.alignedAxis = axis, update.alignedAxisFlipped = flip;
      }
    }
    for (std::size_t s = 0; s < samples.size(); ++s) {
      Vec3f d = current[s].toRotationMatrix().col(update.alignedAxis);
      if (update.alignedAxisFlipped) d = -d;
      // Smallest rotation taking the field's axis onto the tangent, applied to the whole frame.
      rotations[s] = (Quatf::FromTwoVectors(d, samples[s].tangent) * current[s]).normalized();
    }
  }
  update = m.constrain(positions, std::move(rotations), update);
  m.samples.push_back(std::move(samples));
  update.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return update;
}

CurveUpdate FieldDesigner::addFrames(const std::vector<Vec3f>& positions, const std::vector<Quatf>& rotations) {
  auto start = std::chrono::steady_clock::now();
  if (positions.empty() || positions.size() != rotations.size())
    throw ParameterError("positions", "needs one rotation per position, at least one");
  for (const Vec3f& p : positions)
    if (!p.allFinite() || !impl_->grid.contains(p)) throw ParameterError("positions", "must lie inside the field grid");
  std::vector<Quatf> unit;
  for (const Quatf& q : rotations) {
    if (!q.coeffs().allFinite() || !(q.norm() > 1e-6f))
      throw ParameterError("rotations", "must be non-zero and finite");
    unit.push_back(q.normalized());
  }
  CurveUpdate update = impl_->constrain(positions, std::move(unit), CurveUpdate{});
  update.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return update;
}

HarmonicSolveStats FieldDesigner::setConstraints(const std::vector<std::pair<std::int64_t, Quatf>>& targets) {
  for (const auto& [node, q] : targets)
    if (node < 0 || node >= impl_->grid.nodeCount() || !q.coeffs().allFinite() || std::abs(q.norm() - 1.0f) > 1e-3f)
      throw ParameterError("targets", "node " + std::to_string(node) + ": outside the grid or not a unit rotation");
  impl_->solver.clearConstraints();
  if (targets.empty()) {
    impl_->values = FieldValues();
    impl_->field = RotationField(impl_->grid);
    impl_->hasField = false;
    return {};
  }
  for (const auto& [node, q] : targets) impl_->solver.setConstraint(node, toVector(q));
  const HarmonicSolveStats stats = impl_->solver.solve(impl_->values);
  impl_->field = RotationField(impl_->grid, normalizeField(impl_->grid, impl_->values));
  impl_->hasField = true;
  return stats;
}

RotationField FieldDesigner::solveFromScratch() const {
  HarmonicSolver fresh(impl_->grid, impl_->options.solver);
  for (const auto& [node, target] : impl_->solver.constraints()) fresh.setConstraint(node, target);
  FieldValues values;
  fresh.solve(values);
  return RotationField(impl_->grid, normalizeField(impl_->grid, values));
}

FieldDesign designField(const Mesh& mesh, const Sketch& sketch, const FieldDesignOptions& options, Progress& progress,
                        const std::string& source) {
  if (sketch.curves.empty()) throw InputError(source, "has no curves");
  FieldDesigner designer(mesh, options);
  FieldDesign design;
  progress.begin("designing the rotation field", std::int64_t(sketch.curves.size()) + 1);
  for (std::size_t i = 0; i < sketch.curves.size(); ++i) {
    // Unnamed curves are named by their 1-based position, so errors say which one.
    SketchCurve curve = sketch.curves[i];
    if (curve.name.empty()) curve.name.append("#").append(std::to_string(i + 1));  // piecewise: GCC 12 -Wrestrict
    design.updates.push_back(designer.addCurve(curve, source));
    progress.advance(1);
  }
  try {
    design.scales = interpolateScales(designer.grid(), sketch.scalePoints, options.solver.weight);
  } catch (const ParameterError& e) {
    throw InputError(source, e.problem());
  }
  progress.advance(1);
  progress.end();
  design.rotations = designer.field();
  design.curveSamples = designer.curveSamples();
  return design;
}

}  // namespace texsynth
