#pragma once
// GradientSolid: the gradient solid representation (Zhang, Lai & Hu, gradient-solid-textures §3).
// A fixed grid of control points spaced `spacing` voxels apart stores, per control point, a feature
// vector (the colour channels) and its three gradients; any point inside is the tricubic
// interpolation of its cube's 8 corners (tricubic_basis.h), C1 everywhere.
//
// Two regions (§3.2): with `regions`, a signed distance (in voxels) is stored and interpolated the
// same way; control points next to a sign change hold a second feature set for the negative side, and
// a point takes the set of its interpolated sign, so boundaries stay sharp at any magnification.
// Residual detail (§5.4): optionally a per-channel standard deviation sigma, also tricubic, from which
// deterministic Gaussian grain is added at evaluation (one draw per voxel, scaled per channel).
//
// Coordinates are the equivalent raster's voxel units: control (i,j,k) sits at (i,j,k) * spacing, and
// voxel (x,y,z) of the raster the solid stands for is the point (x,y,z). Colours are in [0,1].
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/math.h"

namespace texsynth {

struct GradientSolid {
  Vec3i voxels = Vec3i::Zero();    // the raster it stands for: points span [0, voxels-1] per axis
  Vec3i controls = Vec3i::Zero();  // control points per axis: (voxels - 1) / spacing rounded up, + 1
  int spacing = 4;                 // d: voxels between control points (paper: 4)
  int channels = 3;                // colour channels (1 gray or 3 RGB)

  // Per control point (x fastest), 4 * channels floats: the values, then d/du, d/dv, d/dw of every
  // channel (gradients per cube edge). Control points with one feature set keep it here.
  std::vector<float> positive;

  // Regions (empty without): per control point 4 floats, the signed distance in voxels and its
  // gradients; and for control points next to a sign change, the index of their negative-side set in
  // `negative` (4 * channels floats each), else -1.
  std::vector<float> distance;
  std::vector<std::int32_t> negativeIndex;
  std::vector<float> negative;

  // Residual detail (empty without): per control point 4 * channels floats, sigma and its gradients.
  std::vector<float> detail;

  bool hasRegions() const { return !distance.empty(); }
  bool hasDetail() const { return !detail.empty(); }
  int setSize() const { return 4 * channels; }
  std::int64_t controlCount() const { return std::int64_t(controls.x()) * controls.y() * controls.z(); }
  std::int64_t controlIndex(int i, int j, int k) const {
    return (std::int64_t(k) * controls.y() + j) * controls.x() + i;
  }
  // Control points needed along an axis of `voxels` voxels at `spacing`.
  static int controlsFor(int voxels, int spacing) { return voxels <= 1 ? 2 : (voxels - 2) / spacing + 2; }

  // An empty solid (all zeros, one region) for a raster of `voxels` voxels.
  static GradientSolid zeros(const Vec3i& voxels, int channels, int spacing = 4);

  // Throws InternalError if the arrays and sizes disagree (a programming error, not bad input).
  void checkConsistent() const;
};

struct GradientEvaluateOptions {
  bool exact = true;                                 // exact tricubic; false: the first-order approximation (§4.2.4)
  const class TricubicWeightTable* table = nullptr;  // exact only: weights from this table instead
  bool regions = true;                               // use the two regions when the solid has them
  float antialiasVoxels = 0.0f;  // width of the linear blend across a region boundary (§5.3); 0: sharp
  bool detail = false;           // add the residual grain when the solid has it
  std::uint64_t detailSeed = 0;
};

// Channels values at `point` (voxel units, clamped to the solid's extent) into `out`.
void evaluateGradientSolid(const GradientSolid& solid, const Vec3f& point, const GradientEvaluateOptions& options,
                           float* out);

// The same for a batch of points, channels values each into `out`: faster where consecutive points share
// cubes (slices, volumes, render spans).
void evaluateGradientSolid(const GradientSolid& solid, std::span<const Vec3f> points,
                           const GradientEvaluateOptions& options, float* out);

// The signed distance at `point` (voxels); 0 without regions.
float evaluateGradientDistance(const GradientSolid& solid, const Vec3f& point);

// The whole equivalent raster (solid.voxels), in parallel.
struct Volume;
Volume rasterizeGradientSolid(const GradientSolid& solid, const GradientEvaluateOptions& options = {});

// Root mean square difference, on the 0..255 scale, between `solid` rasterized and `volume`.
double gradientSolidRms(const GradientSolid& solid, const Volume& volume, const GradientEvaluateOptions& options = {});

}  // namespace texsynth
