// Eq. 2: each control point's value and gradients from a first-order Taylor fit to its bucket of voxels.
#include "first_order_fit.h"
#include "texsynth/core/parallel.h"
#include "vectorize_layout.h"

namespace texsynth::vectorize_detail {
namespace {

// `sides` and `sign`: with regions, voxels evaluation puts on the other side weigh kExtendedWeight.
void fitSet(const ControlGrid& grid, int i, int j, int k, const Volume& samples, int channels, float* set,
            const Volume* sides = nullptr, int sign = 0) {
  const int index[3] = {i, j, k};
  int begin[3], end[3];
  for (int a = 0; a < 3; ++a) begin[a] = grid.ownedBegin(a, index[a]), end[a] = grid.ownedEnd(a, index[a]);
  FirstOrderFit fit(channels);
  const double inverse = 1.0 / grid.spacing;
  for (int z = begin[2]; z < end[2]; ++z)
    for (int y = begin[1]; y < end[1]; ++y)
      for (int x = begin[0]; x < end[0]; ++x) {
        const double weight = sides && (sides->at(x, y, z, 0) > 0.5f) != (sign > 0) ? double(kExtendedWeight) : 1.0;
        fit.add((x - i * grid.spacing) * inverse, (y - j * grid.spacing) * inverse, (z - k * grid.spacing) * inverse,
                samples.voxel(x, y, z), weight);
      }
  fit.solve(set);
}

}  // namespace

void fitFirstOrder(const FitLayout& layout, const FitTargets& targets, std::vector<float>& unknowns) {
  const ControlGrid& grid = layout.grid;
  const int channels = layout.channels;
  const std::size_t setSize = 4 * std::size_t(channels);
  unknowns.resize(std::size_t(layout.slots()) * setSize);
  parallelFor(0, grid.controls.z(), [&](std::int64_t k) {
    for (int j = 0; j < grid.controls.y(); ++j)
      for (int i = 0; i < grid.controls.x(); ++i) {
        const std::int64_t control = grid.controlIndex(i, j, int(k));
        const std::int64_t negativeSlot = layout.slot(control, -1);
        if (negativeSlot == control) {
          fitSet(grid, i, j, int(k), *targets.original, channels, &unknowns[std::size_t(control) * setSize]);
        } else {  // next to the boundary: one set per side, each from its side's dilated samples (§4.3)
          fitSet(grid, i, j, int(k), targets.forSide(1), channels, &unknowns[std::size_t(control) * setSize],
                 targets.sides, 1);
          fitSet(grid, i, j, int(k), targets.forSide(-1), channels, &unknowns[std::size_t(negativeSlot) * setSize],
                 targets.sides, -1);
        }
      }
  });
}

}  // namespace texsynth::vectorize_detail
