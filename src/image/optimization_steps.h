#pragma once
// Internal to texture optimization: the least-squares solver's E- and M-steps on one level
// (the discrete solver's are texsynth/image/discrete_steps.h, shared with mesh surfaces), and
// the colors of a map of sources.
#include <cstdint>
#include <span>

#include "texsynth/core/image.h"
#include "texsynth/exemplar/projected_index.h"
#include "texsynth/image/discrete_steps.h"
#include "texsynth/image/optimization_grid.h"

namespace texsynth::detail {

// Least-squares M-step: each active neighborhood's match is the nearest exemplar
// neighborhood in PCA space (KD-tree); its distance is measured in full space.
std::int64_t matchLeastSquares(const OptimizationGrid& grid, const PcaBasis& pca,
                               const ProjectedNeighborhoodIndex& index, const Image& colors, Matches& matches);

// Least-squares E-step with Kwatra's robust weights: each pixel becomes
// sum_p w_p z_p(x) / sum_p w_p, w_p = |x_p - z_p|^(r - 2), over the covering matches.
Image updateLeastSquares(const OptimizationGrid& grid, const Matches& matches, float robustExponent);

// Colors of the grid's stack level at the sources (one exemplar pixel per output pixel).
Image colorsAt(const OptimizationGrid& grid, std::span<const std::int32_t> sources);

}  // namespace texsynth::detail
