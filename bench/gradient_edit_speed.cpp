#include "gradient_edit_speed.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

#include "texsynth/core/parallel.h"
#include "texsynth/core/volume.h"
#include "texsynth/gradient/gradient_edit.h"

namespace texsynth::bench {
namespace {

// A solid `factor` times larger standing for the same texture: each control point takes the value and
// gradients of `solid` at its position (gradients by central differences, per cube edge).
GradientSolid magnified(const GradientSolid& solid, int factor) {
  const Vec3i voxels = solid.voxels * factor;
  GradientSolid large = GradientSolid::zeros(voxels, solid.channels, solid.spacing);
  const int c = solid.channels;
  const float h = 0.25f;
  parallelFor(0, large.controls.z(), [&](std::int64_t k) {
    float plus[4], minus[4];
    for (int j = 0; j < large.controls.y(); ++j)
      for (int i = 0; i < large.controls.x(); ++i) {
        const Vec3f p = Vec3f(float(i), float(j), float(k)) * float(solid.spacing) / float(factor);
        float* set = &large.positive[std::size_t(large.controlIndex(i, j, int(k))) * std::size_t(large.setSize())];
        evaluateGradientSolid(solid, p, {}, set);
        for (int a = 0; a < 3; ++a) {
          evaluateGradientSolid(solid, p + h * Vec3f::Unit(a), {}, plus);
          evaluateGradientSolid(solid, p - h * Vec3f::Unit(a), {}, minus);
          for (int ch = 0; ch < c; ++ch)  // d/dvoxel of the small solid, times spacing / factor per large cube edge
            set[(1 + a) * c + ch] = (plus[ch] - minus[ch]) / (2 * h) * float(solid.spacing) / float(factor);
        }
      }
  });
  return large;
}

double secondsOf(const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void printEditSpeeds(const GradientSolid& solid, int repeats) {
  const int factor = std::max(1, 512 / std::max(1, solid.voxels.maxCoeff()));
  const GradientSolid large = magnified(solid, factor);
  const Vec3f centre = large.voxels.cast<float>() * 0.5f;
  // One stroke through the middle: the program weighs its centres and the edit reaches every control point.
  const std::vector<EditStroke> strokes = {{{centre - Vec3f(60, 20, 0), centre + Vec3f(60, 20, 0)}, 1.0f}};
  EditOptions options;
  options.color = Vec3f(0.8f, 0.2f, 0.8f);
  EditReport solidReport, rasterReport;
  double solidSeconds = 1e30;
  for (int r = 0; r < repeats; ++r) {
    GradientSolid edited = large;  // the edit works in place: a fresh copy each time, outside the timing
    EditReport report;
    const double seconds = secondsOf([&] { report = editGradientSolid(edited, strokes, options); });
    if (seconds < solidSeconds) solidSeconds = seconds, solidReport = report;
  }
  Volume raster = rasterizeGradientSolid(large);
  const double rasterSeconds = secondsOf([&] { rasterReport = editVolume(raster, strokes, options); });
  std::printf(
      "Instant edit (§4.4), %d threads: a %dx%dx%d-equivalent solid (%dx%dx%d control points) and its raster\n\n",
      threadLimit(), large.voxels.x(), large.voxels.y(), large.voxels.z(), large.controls.x(), large.controls.y(),
      large.controls.z());
  std::printf(
      "| edited | stroke voxels | centres | linear program s | update s | total s |\n|---|---:|---:|---:|---:|---:|\n");
  std::printf("| gradient solid (best of %d) | %d | %d | %.3f | %.3f | %.3f |\n", repeats, solidReport.strokeVoxels,
              solidReport.centres, solidReport.lpSeconds, solidReport.updateSeconds, solidSeconds);
  std::printf("| raster volume | %d | %d | %.3f | %.3f | %.3f |\n", rasterReport.strokeVoxels, rasterReport.centres,
              rasterReport.lpSeconds, rasterReport.updateSeconds, rasterSeconds);
  std::printf("\nThe raster edit takes %.0fx the gradient solid's (mean strength deviation %.3f and %.3f).\n",
              rasterSeconds / solidSeconds, solidReport.strengthDeviation, rasterReport.strengthDeviation);
}

}  // namespace texsynth::bench
