#pragma once
// Distances between value distributions (the "histogram" quality metric).
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth {

// Exact Wasserstein-1 (earth mover's) distance between the empirical distributions of two
// non-empty samples of possibly different sizes: the integral of |F_a(t) - F_b(t)| dt.
// Throws ParameterError if either sample is empty.
double wasserstein1(std::vector<float> a, std::vector<float> b);

// Mean over channels of wasserstein1 between channel c of `a` and channel c of `b`, in the
// images' own units. Throws ParameterError if either is empty or their channel counts differ.
double histogramDistance(const Image& a, const Image& b);

}  // namespace texsynth
