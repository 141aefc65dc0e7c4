#pragma once
// Lattice: does an image repeat its content at a shifted offset, as a tiling or a grid of
// copies does? Unlike periodicity (exact duplicate patches at one offset), lattice also sees
// repeats that are shifted by a few pixels from copy to copy, blended or slightly altered.
//
// On the luminance Y (Rec. 709) of an RGB image on the 0..255 scale:
//   1. high-pass: D = Y minus Y blurred by a Gaussian of sigma highPassSigma (borders clamped),
//      so that detail correlates, not slow shading; then D minus its mean;
//   2. R(d) = sum over p of D(p) D(p + d), over the pixels where both lie inside the image
//      (linear, zero-padded autocorrelation, by FFT), divided by that overlap count
//      (W - |dx|)(H - |dy|) and by D's variance, so R(0) = 1; R(d) and R(-d) are averaged;
//   3. offsets with |dx| <= W/2 and |dy| <= H/2 count, except the central lobe: the 4-connected
//      region around the origin where R > lobeThreshold, and every offset with |dx| <= 2 and
//      |dy| <= 2;
//   4. lattice = the largest remaining R that is a local maximum (no higher R among its 8
//      neighbours, lobe included), clamped to 0..1. A repeat is a peak of R; the lobe's flanks,
//      where R falls from the lobe towards 0, are not, so a broad lobe (smooth or elongated
//      detail) does not score the threshold itself.
// A tiling of an exemplar scores close to 1, white noise and good synthesis near 0. A texture
// that is itself a lattice (bricks, tiles) scores high too: compare with the exemplar's own.
// A structure that repeats along a line through the origin (stripes, wood grain, the border
// residue of a smooth ramp) joins the central lobe and does not count. Images whose detail has
// an RMS below 1e-3 (flat, or nearly so) score 0. Deterministic, single-threaded, O(N log N).
#include "texsynth/core/image.h"

namespace texsynth {

struct LatticeOptions {
  double highPassSigma = 4.0;  // Gaussian sigma in pixels of the removed low frequencies (>= 0;
                               // 0 keeps everything but the mean)
  double lobeThreshold = 0.2;  // R above which offsets next to the origin belong to its lobe (0..1)
};

struct LatticePeak {
  double strength = 0;  // the lattice value: the highest peak of R outside the central lobe, 0..1
  int dx = 0, dy = 0;   // its offset, with dy > 0 or (dy == 0 and dx > 0); 0, 0 when none counts
};

// The lattice peak of `rgb255` (any channel count: the first three are R, G, B; one or two
// channels are gray). Throws ParameterError for bad options or non-finite values; an empty
// image, or one too small to have an offset outside the excluded ones, scores 0.
LatticePeak latticePeak(const Image& rgb255, const LatticeOptions& options = {});

// latticePeak(rgb255, options).strength.
double latticeStrength(const Image& rgb255, const LatticeOptions& options = {});

}  // namespace texsynth
