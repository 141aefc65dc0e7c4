#include "texsynth/field/scale_field.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/field/harmonic_solver.h"

namespace texsynth {

ScaleField::ScaleField(const FieldGrid& grid, float value)
    : grid_(grid), scales_(std::size_t(grid.nodeCount()), value) {
  if (!(value > 0) || !std::isfinite(value)) throw ParameterError("scales", "must be positive and finite");
}

ScaleField::ScaleField(const FieldGrid& grid, std::vector<float> scales) : grid_(grid), scales_(std::move(scales)) {
  if (std::int64_t(scales_.size()) != grid.nodeCount())
    throw ParameterError("scales", "has " + std::to_string(scales_.size()) + " entries for " +
                                       std::to_string(grid.nodeCount()) + " grid nodes");
  for (float s : scales_)
    if (!(s > 0) || !std::isfinite(s)) throw ParameterError("scales", "must be positive and finite");
}

float ScaleField::sample(const Vec3f& p) const {
  const FieldGrid::Corners cell = grid_.corners(p);
  float sum = 0;
  for (int corner = 0; corner < 8; ++corner) sum += cell.weight[corner] * scales_[std::size_t(cell.node[corner])];
  return sum;
}

ScaleField interpolateScales(const FieldGrid& grid, const std::vector<ScalePoint>& points, double weight) {
  if (points.empty()) return ScaleField(grid, 1.0f);
  HarmonicSolverOptions options;
  options.weight = weight;
  HarmonicSolver solver(grid, options);
  // Several points on one node: average their log scales.
  std::map<std::int64_t, std::pair<double, int>> perNode;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ScalePoint& p = points[i];
    if (!(p.scale > 0) || !std::isfinite(p.scale))
      throw ParameterError("scalePoints", "point " + std::to_string(i) + " has a non-positive scale");
    if (!p.position.allFinite() || !grid.contains(p.position))
      throw ParameterError("scalePoints", "point " + std::to_string(i) + " lies outside the field grid");
    auto& entry = perNode[grid.nearestNode(p.position)];
    entry.first += std::log(double(p.scale));
    entry.second += 1;
  }
  for (const auto& [node, entry] : perNode)
    solver.setConstraint(node, Eigen::Vector4d(entry.first / entry.second, 0, 0, 0));
  FieldValues values;
  solver.solve(values);
  std::vector<float> scales(std::size_t(grid.nodeCount()));
  for (std::int64_t i = 0; i < grid.nodeCount(); ++i) scales[std::size_t(i)] = float(std::exp(values(i, 0)));
  return ScaleField(grid, std::move(scales));
}

}  // namespace texsynth
