#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "metrics_detail.h"
#include "texsynth/core/error.h"
#include "texsynth/eval/metrics.h"

namespace texsynth {
namespace {

const char* const kAxisNames[3] = {"x", "y", "z"};

int extent(const Volume& volume, int axis) {
  return axis == 0 ? volume.nx : axis == 1 ? volume.ny : volume.nz;
}

// The slice normal to `axis` at `index`; image axes (u, v): x -> (y, z), y -> (x, z), z -> (x, y).
Image volumeSlice(const Volume& volume, int axis, int index) {
  const int uAxis = axis == 0 ? 1 : 0, vAxis = axis == 2 ? 1 : 2;
  Image slice(extent(volume, uAxis), extent(volume, vAxis), volume.channels);
  for (int v = 0; v < slice.height; ++v)
    for (int u = 0; u < slice.width; ++u) {
      int p[3];
      p[axis] = index, p[uAxis] = u, p[vAxis] = v;
      const float* voxel = volume.voxel(p[0], p[1], p[2]);
      std::copy_n(voxel, volume.channels, slice.pixel(u, v));
    }
  return slice;
}

}  // namespace

VolumeQuality evaluateVolume(const Image& exemplar, const Volume& volume, const MetricOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  eval_detail::validateOptions(options);
  if (volume.empty()) throw ParameterError("volume", "is empty");
  const int slices = options.slicesPerAxis;
  for (int axis = 0; axis < 3; ++axis)
    if (slices > extent(volume, axis))
      throw ParameterError("slicesPerAxis", std::to_string(slices) + " slices do not fit the volume's " +
                                                std::to_string(extent(volume, axis)) + " voxels along " +
                                                kAxisNames[axis]);
  const Image exemplarRgb = eval_detail::toRgb255(exemplar, "exemplar", options.patchSize);
  const PatchIndex exemplarIndex(exemplarRgb, options.patchSize);

  VolumeQuality quality;
  for (int axis = 0; axis < 3; ++axis) {
    const auto axisStart = std::chrono::steady_clock::now();
    const int n = extent(volume, axis);
    double coherenceSquares = 0, completenessSquares = 0, histogram = 0, periodicity = 0, lattice = 0, sharpness = 0;
    for (int i = 0; i < slices; ++i) {
      const int index = int(std::floor((i + 0.5) * n / slices));
      const std::string what = std::string("volume slice ") + kAxisNames[axis] + "=" + std::to_string(index);
      Image slice = eval_detail::toRgb255(volumeSlice(volume, axis, index), what, options.patchSize);
      QualityMetrics m = eval_detail::evaluateRgb255(exemplarIndex, slice, options);
      coherenceSquares += m.coherence * m.coherence;
      completenessSquares += m.completeness * m.completeness;
      histogram += m.histogram;
      sharpness += m.sharpness;
      periodicity += m.periodicity;
      lattice += m.lattice;
    }
    QualityMetrics& a = quality.axis[axis];
    a.coherence = std::sqrt(coherenceSquares / slices);
    a.completeness = std::sqrt(completenessSquares / slices);
    a.histogram = histogram / slices;
    a.sharpness = sharpness / slices;
    a.periodicity = periodicity / slices;
    a.lattice = lattice / slices;
    a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - axisStart).count();
  }
  QualityMetrics& mean = quality.mean;
  for (const QualityMetrics& a : quality.axis) {
    mean.coherence += a.coherence / 3;
    mean.completeness += a.completeness / 3;
    mean.histogram += a.histogram / 3;
    mean.sharpness += a.sharpness / 3;
    mean.periodicity += a.periodicity / 3;
    mean.lattice += a.lattice / 3;
  }
  mean.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return quality;
}

}  // namespace texsynth
