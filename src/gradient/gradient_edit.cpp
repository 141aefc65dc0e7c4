// Instant editing (gradient-solid-textures §4.4): fit the influence h once, then one pass over the
// control points (or, for the raster baseline, over the voxels).
#include "texsynth/gradient/gradient_edit.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "edit_tables.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/timing.h"
#include "texsynth/gradient/edit_influence.h"

namespace texsynth {
namespace {

using Clock = std::chrono::steady_clock;

void checkColor(const Vec3f& color) {
  for (int a = 0; a < 3; ++a)
    if (!(color[a] >= 0.0f && color[a] <= 1.0f)) throw ParameterError("color", "components must be in [0, 1]");
}

// Fits the influence to the strokes whose voxels have `colors`, and fills the report's fit fields.
EditInfluence fit(const StrokeVoxels& voxels, const std::vector<float>& colors, int colorChannels,
                  const EditOptions& options, EditReport& report) {
  const auto start = Clock::now();
  EditInfluence influence = fitEditInfluence(voxels, colors, colorChannels, options);
  report.lpSeconds = secondsSince(start);
  report.strokeVoxels = voxels.size();
  report.centres = int(influence.centres.size());
  report.lpRows = influence.lpRows;
  report.weights = influence.weights;
  report.strengthDeviation = influence.deviation;
  return influence;
}

// Everything the per-set update needs besides the set itself.
struct SetUpdate {
  int channels, colorChannels;
  float spacing, alpha, beta;
  std::array<float, 3> reference;
};

// One feature set (values, then d/du, d/dv, d/dw per channel) of the control point at `p` (voxels):
// c' = (1-h) c + h c_ref, and eq. 5 with eq. 6 for the gradients. h >= 1 is clamped to 1, where h
// is flat. Stored gradients are per cube edge: per voxel they are divided by the spacing.
void updateSet(float* set, const Vec3f& p, const InfluenceTables& tables, const float* row, int i, const SetUpdate& u) {
  const int ch = u.channels, cc = u.colorChannels;
  float color255[3] = {0, 0, 0};
  for (int c = 0; c < cc; ++c) color255[c] = 255.0f * set[c];
  const InfluenceSums s = tables.sums<true>(row, i, color255);
  float h = s.s0, dh[3] = {0, 0, 0};  // dh: per cube edge
  if (h >= 1.0f) {
    h = 1.0f;
  } else {
    for (int a = 0; a < 3; ++a) {
      // J^T (c S0 - Sc), with J = dc/dp per voxel on the 0..255 scale.
      float colorTerm = 0;
      for (int c = 0; c < cc; ++c)
        colorTerm += (255.0f / u.spacing) * set[(1 + a) * ch + c] * (color255[c] * s.s0 - s.sc[c]);
      const float perVoxel = -2.0f * u.alpha * (u.beta * (p[a] * s.s0 - s.sp[a]) + colorTerm);
      dh[a] = perVoxel * u.spacing;
    }
  }
  for (int c = 0; c < cc; ++c) {
    const float value = set[c], offset = value - u.reference[std::size_t(c)];
    set[c] = (1.0f - h) * value + h * u.reference[std::size_t(c)];
    for (int a = 0; a < 3; ++a) set[(1 + a) * ch + c] = (1.0f - h) * set[(1 + a) * ch + c] - offset * dh[a];
  }
}

}  // namespace

EditReport editGradientSolid(GradientSolid& solid, const std::vector<EditStroke>& strokes, const EditOptions& options) {
  solid.checkConsistent();
  checkColor(options.color);
  const int cc = editColorChannels(solid.channels);
  const StrokeVoxels voxels = rasterizeStrokes(strokes, solid.voxels);
  // Stroke colours: the solid's exact values there, as a raster of it would hold them.
  std::vector<float> colors(std::size_t(voxels.size()) * std::size_t(cc));
  parallelFor(0, voxels.size(), [&](std::int64_t v) {
    float values[4];
    evaluateGradientSolid(solid, voxels.positions[std::size_t(v)].cast<float>(), GradientEvaluateOptions{}, values);
    std::copy(values, values + cc, &colors[std::size_t(v) * std::size_t(cc)]);
  });
  EditReport report;
  const EditInfluence influence = fit(voxels, colors, cc, options, report);

  const auto start = Clock::now();
  const InfluenceTables tables(influence, solid.controls, float(solid.spacing));
  if (!tables.empty()) {
    const SetUpdate update{solid.channels, cc,           float(solid.spacing),
                           options.alpha,  options.beta, editReference(options.color, cc)};
    const std::size_t setSize = std::size_t(solid.setSize());
    const std::int64_t rows = std::int64_t(solid.controls.z()) * solid.controls.y();
    parallelForChunks(0, rows, 16, [&](std::int64_t begin, std::int64_t end) {
      std::vector<float> row(std::size_t(tables.padded()));
      for (std::int64_t r = begin; r < end; ++r) {
        const int j = int(r % solid.controls.y()), l = int(r / solid.controls.y());
        tables.rowFactors(j, l, row.data());
        for (int i = 0; i < solid.controls.x(); ++i) {
          const std::int64_t control = solid.controlIndex(i, j, l);
          const Vec3f p = Vec3f(float(i), float(j), float(l)) * float(solid.spacing);
          updateSet(&solid.positive[std::size_t(control) * setSize], p, tables, row.data(), i, update);
          // A boundary point's negative-side set sits at the same position, with its own colour.
          const std::int32_t negative = solid.hasRegions() ? solid.negativeIndex[std::size_t(control)] : -1;
          if (negative >= 0)
            updateSet(&solid.negative[std::size_t(negative) * setSize], p, tables, row.data(), i, update);
        }
      }
    });
  }
  report.updateSeconds = secondsSince(start);
  return report;
}

EditReport editVolume(Volume& volume, const std::vector<EditStroke>& strokes, const EditOptions& options) {
  if (volume.empty()) throw ParameterError("volume", "is empty");
  checkColor(options.color);
  const int cc = editColorChannels(volume.channels);
  const Vec3i extent(volume.nx, volume.ny, volume.nz);
  const StrokeVoxels voxels = rasterizeStrokes(strokes, extent);
  std::vector<float> colors(std::size_t(voxels.size()) * std::size_t(cc));
  for (int v = 0; v < voxels.size(); ++v) {
    const Vec3i& p = voxels.positions[std::size_t(v)];
    const float* values = volume.voxel(p.x(), p.y(), p.z());
    std::copy(values, values + cc, &colors[std::size_t(v) * std::size_t(cc)]);
  }
  EditReport report;
  const EditInfluence influence = fit(voxels, colors, cc, options, report);

  const auto start = Clock::now();
  const InfluenceTables tables(influence, extent, 1.0f);
  if (!tables.empty()) {
    const std::array<float, 3> reference = editReference(options.color, cc);
    parallelForChunks(0, std::int64_t(volume.nz) * volume.ny, 16, [&](std::int64_t begin, std::int64_t end) {
      std::vector<float> row(std::size_t(tables.padded()));
      for (std::int64_t r = begin; r < end; ++r) {
        const int y = int(r % volume.ny), z = int(r / volume.ny);
        tables.rowFactors(y, z, row.data());
        for (int x = 0; x < volume.nx; ++x) {
          float* voxel = volume.voxel(x, y, z);
          float color255[3] = {0, 0, 0};
          for (int c = 0; c < cc; ++c) color255[c] = 255.0f * voxel[c];
          const float h = std::min(tables.sums<false>(row.data(), x, color255).s0, 1.0f);
          for (int c = 0; c < cc; ++c) voxel[c] = (1.0f - h) * voxel[c] + h * reference[std::size_t(c)];
        }
      }
    });
  }
  report.updateSeconds = secondsSince(start);
  return report;
}

}  // namespace texsynth
