#pragma once
// Internal to gradient synthesis: one iteration of one level, swept through the solid in z order of
// cube layers (§4.2.2): match check points, fill buckets (two passes at the finest level), refit each
// control layer by eq. 2 once no check point can reach its buckets any more, and free those buckets.
#include <cstdint>
#include <functional>

#include "synthesis_context.h"
#include "texsynth/core/progress.h"

namespace texsynth::gradient_synthesis {

// A bucket layer whose samples are complete: z (bucket index), per bucket `features` averages and a
// filled flag (0 where no sample fell).
struct ClosedLayer {
  int z = 0;
  const float* averages = nullptr;
  const std::uint8_t* filled = nullptr;
};

struct SweepStats {
  std::int64_t checkPoints = 0;
  std::int64_t peakBucketBytes = 0;
};

// Runs the iteration on `state` (feature-vector solid, one region). `closed`, if given, sees every bucket
// layer in z order when it closes, before its control layer is refitted. Same bits for any thread count,
// with or without bucket reuse.
// `progress` advances by one per cube layer matched.
void sweepIteration(const LevelContext& ctx, GradientSolid& state, SweepStats& stats,
                    const std::function<void(const ClosedLayer&)>& closed = {}, Progress& progress = noProgress());

}  // namespace texsynth::gradient_synthesis
