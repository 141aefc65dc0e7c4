#pragma once
// The paper's E+M iterations (Han et al., "Fast example-based surface texture synthesis via
// discrete optimization", Table 1: k-coherence M-step with the usage term, random candidates and
// weighted votes of 2D optimize) on CONTINUOUS exemplar coordinates (surface_parallel.h). The
// discrete solver shared with images (image/discrete_steps.h) compares resampled neighborhoods
// of whole-pixel sources and takes the candidate nearest all votes; on a mesh that washes a
// surface out (GIMP brick on the CGAL bunny: flatness -0.09 before, 0.60 after). Here a
// neighborhood is compared at its members' own flattened offsets (a coherent copy costs 0),
// matches are continuous positions, every vote carries its sub-pixel part, and each vertex takes
// its strongest vote, votes within a pixel of each other counted together (see update() in
// surface_optimization.cpp for why not the consensus).
#include <cstddef>
#include <span>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/progress.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/image/texture_optimization.h"
#include "texsynth/surface/surface_neighborhoods.h"

namespace texsynth {

// E+M at stack `level` on the active neighborhoods `neighborhoods` (of size
// options.neighborhoodSizes[scale]): the matches of the coordinates as they come in, then up to
// options.maxIterations E+M steps until no match changes. Candidates: the k-coherence sets of
// `analysis` (analyses.back() of optimizationAnalysisOptions) and options.randomCandidates random
// positions; options.coverageWeight the usage term, options.voteExponent the vote weights;
// histogramWeight a color histogram term (image/color_histogram_cost.h) of histogramWeight *
// sigma * (share / exemplar share - 1) per member, 0 = none. Appends one OptimizationIteration per
// M-step. Deterministic for any thread count.
void optimizeSurfaceCoordinates(const SurfaceNeighborhoods& neighborhoods, const ExemplarAnalysis& analysis, int level,
                                std::size_t scale, const TextureOptimizationOptions& options,
                                std::vector<Vec2f>& coordinates, std::vector<OptimizationIteration>& history,
                                Progress& progress, float histogramWeight = 0.0f);

}  // namespace texsynth
