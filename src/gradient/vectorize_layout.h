#pragma once
// Internal to vectorization: which voxels each cube and control point covers, which feature set of
// a control point each cube's samples fit, and where the samples' target values come from.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/volume.h"

namespace texsynth::vectorize_detail {

struct ControlGrid {
  Vec3i voxels, controls;
  int spacing;

  std::int64_t controlIndex(int i, int j, int k) const {
    return (std::int64_t(k) * controls.y() + j) * controls.x() + i;
  }
  std::int64_t controlCount() const { return std::int64_t(controls.x()) * controls.y() * controls.z(); }
  int cubes(int axis) const { return controls[axis] - 1; }
  std::int64_t cubeCount() const { return std::int64_t(cubes(0)) * cubes(1) * cubes(2); }
  std::int64_t cubeIndex(int i, int j, int k) const { return (std::int64_t(k) * cubes(1) + j) * cubes(0) + i; }
  // Voxels [begin, end) of cube c along `axis`: the last cube also takes the far face.
  int cubeBegin(int, int c) const { return c * spacing; }
  int cubeEnd(int axis, int c) const {
    return c == controls[axis] - 2 ? voxels[axis] : std::min((c + 1) * spacing, voxels[axis]);
  }
  // Voxels [begin, end) nearest to control i along `axis` (eq. 2's buckets); a control past the last
  // voxel takes the last one, so every control point has samples.
  int ownedBegin(int axis, int i) const { return std::min(std::max(0, i * spacing - spacing / 2), voxels[axis] - 1); }
  int ownedEnd(int axis, int i) const {
    const int end =
        i == controls[axis] - 1 ? voxels[axis] : std::min(voxels[axis], i * spacing - spacing / 2 + spacing);
    return std::max(end, ownedBegin(axis, i) + 1);
  }
};

// Which feature sets a cube's samples fit: one region's (the cube lies on one side of the mask's
// boundary), or both (the boundary crosses it).
enum class CubeSides : std::uint8_t { Positive, Negative, Both };

struct FitLayout {
  ControlGrid grid;
  int channels = 3;
  std::vector<CubeSides> cubeSides;                          // empty: every cube Positive (one region)
  const std::vector<std::int32_t>* negativeIndex = nullptr;  // null without regions
  std::int64_t negatives = 0;

  std::int64_t slots() const { return grid.controlCount() + negatives; }
  // The unknown set a sample of `sign` (> 0 or < 0) uses at `control`, as evaluation picks it.
  std::int64_t slot(std::int64_t control, int sign) const {
    if (sign >= 0 || !negativeIndex) return control;
    const std::int32_t index = (*negativeIndex)[std::size_t(control)];
    return index < 0 ? control : grid.controlCount() + index;
  }
  CubeSides sides(std::int64_t cube) const {
    return cubeSides.empty() ? CubeSides::Positive : cubeSides[std::size_t(cube)];
  }
};

// Target values of the samples: the voxels themselves, and with regions each side's values carried
// across the boundary (dilation, §4.3) for the sets that reach over it.
struct FitTargets {
  const Volume* original = nullptr;
  const Volume* positive = nullptr;  // null without regions
  const Volume* negative = nullptr;
  const Volume* sides = nullptr;  // with regions: 1 where evaluation takes the positive side, else 0
  const Volume& forSide(int sign) const { return sign > 0 ? *positive : *negative; }
};

// How much a value carried across the boundary counts next to a voxel of the side itself.
inline constexpr float kExtendedWeight = 0.1f;

// Eq. 2 at every control point: first-order least squares over the voxels nearest to it, into
// `unknowns` (layout.slots() sets of 4 * channels floats).
void fitFirstOrder(const FitLayout& layout, const FitTargets& targets, std::vector<float>& unknowns);

// Eq. 3: least squares of the exact tricubic evaluation against every sample, by Jacobi-preconditioned
// conjugate gradients from the current `unknowns`.
void refineControlPoints(const FitLayout& layout, const FitTargets& targets, int iterations,
                         std::vector<float>& unknowns);

}  // namespace texsynth::vectorize_detail
