#pragma once
// Each fuzz target keeps to one core: scripts/fuzz.sh runs JOBS of them side by side, and the
// decoders then work on the calling thread instead of starting threads for every input.
#include "texsynth/core/parallel.h"

namespace texsynth::fuzz {
inline ThreadLimit oneThread{1};
}  // namespace texsynth::fuzz
