#pragma once
// Evaluation speed of gradient solids: single points through evaluateGradientSolid, on all threads.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "texsynth/gradient/gradient_solid.h"

namespace texsynth::bench {

// Prints a Markdown table, M points/s per solid, point order (uniformly random = shuffled; slice
// order = a regular grid walked x fastest) and evaluation: exact, TricubicWeightTable(33) and (17),
// first order. Best of `repeats` runs each, `points` points per run.
void printEvaluationSpeeds(const std::vector<std::pair<std::string, const GradientSolid*>>& solids, std::int64_t points,
                           int repeats = 2);

}  // namespace texsynth::bench
