#include "texsynth/animation/flow_animation.h"

#include <cmath>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

void validateFlowAnimationOptions(const FlowAnimationOptions& options) {
  if (!(options.coherence >= 0.0f && options.coherence <= kMaxFlowCoherence))
    throw ParameterError("coherence",
                         "must be a finite number in [0, 1e+06], got " + std::to_string(options.coherence));
  if (options.iterations < 1 || options.iterations > 20)
    throw ParameterError("iterations", "must be in 1..20, got " + std::to_string(options.iterations));
  if (options.randomCandidates < 0 || options.randomCandidates > 1024)
    throw ParameterError("randomCandidates", "must be in 0..1024, got " + std::to_string(options.randomCandidates));
  if (options.frameStrideDivisor < 1 || options.frameStrideDivisor > 16)
    throw ParameterError("frameStrideDivisor", "must be in 1..16, got " + std::to_string(options.frameStrideDivisor));
}

}  // namespace texsynth
