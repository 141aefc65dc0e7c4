#pragma once
// ScaleField: a positive scalar per grid node (the paper's generalization from rotations to
// tensors with varying scale), sampled trilinearly.
#include <vector>

#include "texsynth/field/field_grid.h"

namespace texsynth {

struct ScalePoint {
  Vec3f position = Vec3f::Zero();
  float scale = 1;  // > 0
};

class ScaleField {
 public:
  ScaleField() = default;
  // Every node `value`.
  explicit ScaleField(const FieldGrid& grid, float value = 1);
  // Throws ParameterError("scales", ...) on a size mismatch or a non-positive / non-finite value.
  ScaleField(const FieldGrid& grid, std::vector<float> scales);
  const FieldGrid& grid() const { return grid_; }
  const std::vector<float>& scales() const { return scales_; }
  float sample(const Vec3f& p) const;

 private:
  FieldGrid grid_;
  std::vector<float> scales_;
};

// Harmonic interpolation of sparse scale points over the grid (same energy as the rotations:
// ||L s||^2 + weight^2 * sum (s(v) - s_v)^2 at each point's nearest node), interpolating
// log(scale) so the result stays positive. No points: scale 1 everywhere. Throws
// ParameterError("scalePoints", ...) for a point outside the grid or a non-positive scale.
ScaleField interpolateScales(const FieldGrid& grid, const std::vector<ScalePoint>& points, double weight = 100);

}  // namespace texsynth
