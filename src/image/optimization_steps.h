#pragma once
// Internal to texture optimization: the E- and M-steps of the two solvers on one level.
// Every step reads only the state before it and writes a new one, pixel by pixel or
// neighborhood by neighborhood, so results never depend on scheduling.
#include <cstdint>

#include "optimization_grid.h"
#include "optimization_usage.h"
#include "texsynth/core/image.h"
#include "texsynth/exemplar/projected_index.h"
#include "texsynth/image/parallel_synthesis.h"

namespace texsynth::detail {

// What the discrete M-step adds to plain k-coherence.
struct DiscreteStepOptions {
  const UsageMap* usage = nullptr;  // the usage term; null = none
  int randomCandidates = 0;         // uniformly random exemplar neighborhoods per match
  std::uint64_t randomKey = 0;      // their hash key (seed, level, size, iteration)
};

// Discrete M-step: each active neighborhood's match becomes the best of its k-coherence
// candidates (the exemplar neighborhoods that the coordinates of its pixels propose, with
// their similarity sets at `level` of `similarity`) and random ones, ranked in the PCA space
// of `pcaLevel` (this neighborhood size's analysis); the winner replaces the current match
// only if it is nearer in full space, usage term included. Returns how many matches changed.
std::int64_t matchDiscrete(const OptimizationGrid& grid, const ExemplarLevel& pcaLevel,
                           const ExemplarAnalysis& similarity, int level, const SourceCoordinates& coords,
                           const DiscreteStepOptions& step, Matches& matches);

// Discrete E-step (grid.norm must be Euclidean): each pixel takes, among the pixels its
// covering matches vote for, their similarity sets and its current source, the one with the
// least weighted sum of color distances to the votes. A vote weighs (d_p + 0.01)^-voteExponent,
// d_p its match's mean color distance per pixel (Kwatra's robust weights; 0 = equal votes).
SourceCoordinates updateDiscrete(const OptimizationGrid& grid, const ExemplarAnalysis& analysis, int level,
                                 const SourceCoordinates& coords, float voteExponent, const Matches& matches);

// Least-squares M-step: each active neighborhood's match is the nearest exemplar
// neighborhood in PCA space (KD-tree); its distance is measured in full space.
std::int64_t matchLeastSquares(const OptimizationGrid& grid, const PcaBasis& pca,
                               const ProjectedNeighborhoodIndex& index, const Image& colors, Matches& matches);

// Least-squares E-step with Kwatra's robust weights: each pixel becomes
// sum_p w_p z_p(x) / sum_p w_p, w_p = |x_p - z_p|^(r - 2), over the covering matches.
Image updateLeastSquares(const OptimizationGrid& grid, const Matches& matches, float robustExponent);

// Colors of the grid's stack level at the coordinates.
Image colorsAt(const OptimizationGrid& grid, const SourceCoordinates& coords);

}  // namespace texsynth::detail
