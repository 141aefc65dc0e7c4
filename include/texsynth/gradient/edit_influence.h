#pragma once
// The influence h of a gradient-solid edit (gradient-solid-textures eq. 4): the stroke voxels, the
// RBF centres drawn from them and their non-negative weights from the linear program. Shared by
// editGradientSolid and editVolume so both edits agree given the same stroke colours.
#include <array>
#include <cstdint>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/gradient/gradient_edit.h"

namespace texsynth {

// Voxels the strokes pass through, each with its stroke's strength, in order of first appearance.
struct StrokeVoxels {
  std::vector<Vec3i> positions;
  std::vector<float> strengths;
  int size() const { return int(positions.size()); }
};

// Samples each polyline every half voxel or less and keeps the nearest voxels inside [0, extent-1]
// (parts outside the raster are dropped); a voxel on several strokes takes the latest stroke's
// strength. Throws ParameterError("strokes") for no strokes, bad values or no voxel inside.
StrokeVoxels rasterizeStrokes(const std::vector<EditStroke>& strokes, const Vec3i& extent);

// How many leading channels an edit compares and recolours: 3 for RGB(A), else 1 (gray, gray+alpha).
int editColorChannels(int channels);

// The reference colour for `colorChannels` channels: RGB, or its Rec. 709 luminance for gray.
std::array<float, 3> editReference(const Vec3f& color, int colorChannels);

struct EditInfluence {
  float alpha = 0, beta = 0;
  int colorChannels = 3;
  std::vector<Vec3f> centres;                      // positions, voxels
  std::vector<std::array<float, 3>> centreColors;  // 0..255 scale
  std::vector<double> weights;                     // omega_k >= 0
  int lpRows = 0;                                  // stroke voxels the program fitted
  double deviation = 0;                            // mean |min(h, 1) - strength| over them

  // h (eq. 4) at `point` (voxels) for `color` ([0,1], colorChannels values), before clamping.
  double operator()(const Vec3f& point, const float* color) const;
  // Centre k's RBF h_{i,k} there, without its weight.
  double term(std::size_t k, const Vec3f& point, const float* color) const;
};

// Draws min(options.centres, voxels) centres (hashKey with options.seed) and solves the linear
// program min sum_j |h_j - s_j| over at most kEditLpRows stroke voxels for weights >= 0.
// `colors` holds colorChannels values in [0,1] per stroke voxel.
inline constexpr int kEditLpRows = 2000;
EditInfluence fitEditInfluence(const StrokeVoxels& voxels, const std::vector<float>& colors, int colorChannels,
                               const EditOptions& options);

}  // namespace texsynth
