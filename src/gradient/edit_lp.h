#pragma once
// Internal to the gradient module: the linear program of gradient-solid edits.
#include <vector>

namespace texsynth {

// Weights w >= 0 minimizing sum_j |sum_k a(j,k) w_k - s_j| (an L1 fit), solved with GLPK's simplex.
// `a` is rows x cols, row-major; `s` has `rows` entries. Throws InternalError if GLPK fails.
std::vector<double> solveNonNegativeL1(const std::vector<double>& a, const std::vector<double>& s, int cols);

}  // namespace texsynth
