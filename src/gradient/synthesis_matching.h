#pragma once
// Internal to gradient synthesis: matching a check point's three slices to exemplar patches (§4.2.1).
#include <algorithm>

#include "synthesis_context.h"

namespace texsynth::gradient_synthesis {

// Samples the check point's slices from `state` by the first-order evaluation (§4.2.4), turned by its
// frame, and finds its patches: E_x nearest in PCA space, then (with crossbar matching) E_y among the N1
// patches whose z crossbar agrees best with E_x's, E_z among the N2 agreeing best on both of its
// crossbars; without crossbar matching each nearest on its own. Fills cp.pixel. Thread-safe.
void matchCheckPoint(const LevelContext& ctx, const GradientSolid& state, CheckPoint& cp);

// The first-order value of `state` at `point` (clamped to the solid), `state.channels` floats: the nearest
// control point's values plus its gradients times the offset (§4.2.4). Inline: slices take ~1300 per check point.
inline void sampleFirstOrder(const GradientSolid& state, const Vec3f& point, float* out) {
  const float inverse = 1.0f / float(state.spacing);
  int nearest[3];
  float offset[3];
  for (int a = 0; a < 3; ++a) {
    const float p = std::clamp(point[a], 0.0f, float(state.voxels[a] - 1)) * inverse;
    nearest[a] = std::min(int(p + 0.5f), state.controls[a] - 1);
    offset[a] = p - float(nearest[a]);
  }
  const int f = state.channels;
  const float* s = &state.positive[std::size_t(state.controlIndex(nearest[0], nearest[1], nearest[2])) *
                                   std::size_t(state.setSize())];
  for (int c = 0; c < f; ++c)
    out[c] = s[c] + offset[0] * s[f + c] + offset[1] * s[2 * f + c] + offset[2] * s[3 * f + c];
}

}  // namespace texsynth::gradient_synthesis
