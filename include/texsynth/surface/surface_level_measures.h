#pragma once
// Cheap measures of one level's synthesized coordinates against the exemplar's stack level, for
// deciding between two states of a level (the start and its E+M refinement): how much of the
// surface is flat, and how far its colors' histogram is from the exemplar's.
#include <span>

#include "texsynth/core/math.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/surface/surface_stencil.h"

namespace texsynth {

// The share of an exemplar's pixels that are distinctive (distinctive_colors.h) in surface
// synthesis: its measures and its feature channel.
constexpr int kDistinctivePercent = 20;

struct SurfaceLevelMeasures {
  // The share of vertices whose stencil (their own colors, not resampled) has a lower standard
  // deviation than the exemplar level's 10th-percentile neighbourhood of the same size, minus
  // 0.10: about 0 for a faithful texture, 0.9 for one color everywhere.
  double flatness = 0;
  // Mean over channels of the Wasserstein-1 distance between the vertices' colors and the level's
  // pixels (color units of the level, 0..1).
  double histogram = 0;
  // The share of vertices whose color is farther from the level's median color than four fifths
  // of its pixels are: the exemplar's distinctive colors (about 0.2 when faithful; the sparse dark
  // features of a flat-background exemplar, whose flatness above cannot see them, when most of
  // its patches are flat).
  double distinctive = 0;
};

// The measures of `coordinates` (one per stencil vertex; nearest-pixel colors of `level`, its
// feature channel too where the analysis has one).
SurfaceLevelMeasures measureSurfaceLevel(const SurfaceStencil& stencil, const ExemplarLevel& level,
                                         std::span<const Vec2f> coordinates);

}  // namespace texsynth
