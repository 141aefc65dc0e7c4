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

int largestOddAtMost(int n) {
  return n % 2 ? n : n - 1;
}

// Checks that need only the volume's size and values, so a patch that fits no slice or a NaN
// voxel is refused before the exemplar is indexed (for large patches that alone takes seconds).
void checkVolume(const Volume& volume, const MetricOptions& options) {
  if (volume.empty()) throw ParameterError("volume", "is empty");
  const std::string size =
      std::to_string(volume.nx) + "x" + std::to_string(volume.ny) + "x" + std::to_string(volume.nz);
  for (int axis = 0; axis < 3; ++axis)
    if (options.slicesPerAxis > extent(volume, axis))
      throw ParameterError("slicesPerAxis", std::to_string(options.slicesPerAxis) + " slices do not fit the volume's " +
                                                std::to_string(extent(volume, axis)) + " voxels along " +
                                                kAxisNames[axis]);
  // The slices with the shortest side decide; name those.
  int tightest = 0;
  auto shortSide = [&](int axis) {
    return std::min(extent(volume, axis == 0 ? 1 : 0), extent(volume, axis == 2 ? 1 : 2));
  };
  for (int axis = 1; axis < 3; ++axis)
    if (shortSide(axis) < shortSide(tightest)) tightest = axis;
  if (options.patchSize > shortSide(tightest)) {
    const int width = extent(volume, tightest == 0 ? 1 : 0), height = extent(volume, tightest == 2 ? 1 : 2);
    throw ParameterError("patchSize", std::to_string(options.patchSize) + " is larger than the " +
                                          std::to_string(width) + "x" + std::to_string(height) + " slices normal to " +
                                          kAxisNames[tightest] + " of the " + size + " volume (at most " +
                                          std::to_string(largestOddAtMost(shortSide(tightest))) + " fits every slice)");
  }
  for (std::size_t i = 0; i < volume.voxels.size(); ++i)
    if (!std::isfinite(volume.voxels[i])) {
      const std::size_t voxel = i / std::size_t(volume.channels);
      throw ParameterError("volume", "voxel (" + std::to_string(voxel % volume.nx) + ", " +
                                         std::to_string(voxel / volume.nx % volume.ny) + ", " +
                                         std::to_string(voxel / (std::size_t(volume.nx) * volume.ny)) +
                                         ") holds a non-finite value (NaN or infinity)");
    }
}

}  // namespace

VolumeQuality evaluateVolume(const Image& exemplar, const Volume& volume, const MetricOptions& options,
                             Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  eval_detail::validateOptions(options);
  checkVolume(volume, options);
  const int slices = options.slicesPerAxis;
  const Image exemplarRgb = eval_detail::toRgb255(exemplar, "exemplar", options.patchSize);
  progress.begin("indexing exemplar patches", 1);
  const PatchIndex exemplarIndex(exemplarRgb, options.patchSize);
  progress.advance();
  progress.end();

  VolumeQuality quality;
  progress.begin("evaluating slices", 3 * std::int64_t(slices));
  for (int axis = 0; axis < 3; ++axis) {
    const auto axisStart = std::chrono::steady_clock::now();
    const int n = extent(volume, axis);
    double coherenceSquares = 0, completenessSquares = 0, histogram = 0, periodicity = 0, lattice = 0, sharpness = 0,
           tail = 0;
    for (int i = 0; i < slices; ++i) {
      const int index = int(std::floor((i + 0.5) * n / slices));
      // checkVolume made every slice fit the patch and hold finite values.
      Image slice = eval_detail::toRgb255(volumeSlice(volume, axis, index), "volume", options.patchSize);
      QualityMetrics m = eval_detail::evaluateRgb255(exemplarIndex, slice, options);
      progress.advance();
      coherenceSquares += m.coherence * m.coherence;
      tail += m.coherenceTail;
      completenessSquares += m.completeness * m.completeness;
      histogram += m.histogram;
      sharpness += m.sharpness;
      periodicity += m.periodicity;
      lattice += m.lattice;
    }
    QualityMetrics& a = quality.axis[axis];
    a.coherence = std::sqrt(coherenceSquares / slices);
    a.coherenceTail = tail / slices;
    a.completeness = std::sqrt(completenessSquares / slices);
    a.histogram = histogram / slices;
    a.sharpness = sharpness / slices;
    a.periodicity = periodicity / slices;
    a.lattice = lattice / slices;
    a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - axisStart).count();
  }
  progress.end();
  QualityMetrics& mean = quality.mean;
  for (const QualityMetrics& a : quality.axis) {
    mean.coherence += a.coherence / 3;
    mean.coherenceTail += a.coherenceTail / 3;
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
