#pragma once
// Vectorization of voxel solids into gradient solids (gradient-solid-textures §5.2, §4.2.2, §4.3).
//
// Every voxel is a sample. The first-order fit solves, per control point, the small least-squares
// problem of eq. 2 over the voxels nearest to it (a first-order Taylor expansion). With `optimize`,
// the control points are then refined against the exact tricubic evaluation of every sample (eq. 3):
// a sparse least-squares problem solved by conjugate gradients warm-started from the first-order fit.
// With a mask, the two regions are separated (§4.3): the signed distance to the mask's boundary is
// fitted first (always refined), control points of cubes its sign changes in get a positive and a
// negative set, each fitted from the voxels the stored distance puts on its side (as evaluation will)
// plus its side's values carried a few voxels across the boundary (dilation, weighing 0.1).
// With `detail`, the residuals' per-channel sigma is fitted too (§5.4).
#include <cstdint>

#include "texsynth/core/progress.h"
#include "texsynth/core/volume.h"
#include "texsynth/gradient/gradient_solid.h"

namespace texsynth {

struct VectorizeOptions {
  int spacing = 4;        // d, voxels between control points (paper: 4)
  bool optimize = false;  // refine by eq. 3 (paper: Table 1 "w/ opt.")
  int iterations = 6;     // conjugate-gradient iterations of the refinement (converged by then on the test volumes)
  bool detail = false;    // fit residual sigma (§5.4)
  bool quantize = true;   // round to the .tsgs file's 8-bit values before measuring
};

struct VectorizeReport {
  double fitSeconds = 0;       // first-order fit (with regions: distance and dilation included)
  double optimizeSeconds = 0;  // eq. 3 refinement
  double totalSeconds = 0;
  double rms = 0;  // 0..255, over all voxels and channels, of the (quantized) result
  std::int64_t boundaryControls = 0;
};

// `volume`: the voxels (1 or 3 channels, values in [0,1]; 4 channels: alpha is dropped). `mask`:
// empty, or a 1-channel volume of the same size, > 0.5 inside the positive region. Throws
// ParameterError("volume" | "mask" | "spacing" | "iterations", ...) for bad input.
GradientSolid vectorizeVolume(const Volume& volume, const Volume& mask, const VectorizeOptions& options = {},
                              VectorizeReport* report = nullptr, Progress& progress = noProgress());

// The signed Euclidean distance (voxels) from every voxel centre to the boundary of `mask` (> 0.5
// inside, positive inside), clamped to +-limit. Exact (separable squared-distance transform).
Volume signedDistanceVolume(const Volume& mask, float limit);

}  // namespace texsynth
