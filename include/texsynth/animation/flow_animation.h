#pragma once
// Frame-coherent flow animation by discrete optimization (Han et al., "Fast example-based
// surface texture synthesis via discrete optimization", Table 1 with E_c; Kwatra et al. 2005
// §4): a texture that flows along a (possibly changing) velocity field, frame after frame,
// staying both coherent in time and faithful to the exemplar.
//
// Frame 0 is a static synthesis. For every further frame the previous frame's exemplar
// positions are carried along the flow (flow_advection.h): their colors are the constraint u of
// E(x) = E_t(x; {z_p}) + lambda E_c(x; u), and the advected sources are the start of E+M
// iterations at the finest level with the last neighborhood size (the discrete M-step as in
// static synthesis; the E-step adds lambda W |x - u| to every candidate's cost, W the sample's
// total vote weight). Where the flow keeps the texture intact (translation, slow rotation) the
// advected sources already match the exemplar and stay; where it stretches or compresses it
// (sources, sinks, shear) the matches stop agreeing with u and the solver grows new texture.
// lambda = 0 gives independent frames (each a fresh static synthesis with its own seed); a large
// lambda gives pure advection (nothing but transport; the texture drifts and smears).
//
// Deterministic for any thread count: frame t depends only on the seed, the options and the
// velocities of frames 0 .. t-1.
#include <cstdint>

namespace texsynth {

// Largest lambda of E_c: far past the point where frames are pure advection.
inline constexpr float kMaxFlowCoherence = 1e6f;

struct FlowAnimationOptions {
  // lambda: the weight of the previous frame carried along the flow against all the votes of the
  // neighborhoods a sample lies in. 0 = independent frames; >= 1e6 acts as pure advection.
  float coherence = 0.1f;
  // E+M steps per frame at the finest level (1 keeps frames fast; 2 repairs stretched texture
  // sooner).
  int iterations = 1;
  // On images: frame neighborhoods' centres N/frameStrideDivisor apart (2: N/2, a quarter of
  // static synthesis's N/4 active set; 4: as static synthesis). Surfaces use their prepared set.
  int frameStrideDivisor = 2;
  // Random candidates per match in a frame's M-step (static synthesis: 16). A frame starts from
  // a good texture, so a few keep the exemplar's rare parts within reach; with fewer candidates
  // than the full-space shortlist a coherent neighborhood skips the PCA ranking (pink marble,
  // vortex at 256²: 0.094 s per frame against 0.144 s with 16, frame 60 coherence 3.07 against 3.17).
  int randomCandidates = 4;
};

// Throws ParameterError("coherence" or "iterations", ...) for a negative or non-finite lambda or
// iterations outside 1..20.
void validateFlowAnimationOptions(const FlowAnimationOptions& options);

struct FrameStatistics {
  int frame = 0;
  double seconds = 0;         // wall time of the whole frame (advection, solver, measures)
  double advectSeconds = 0;   // carrying the previous frame along the flow
  double solveSeconds = 0;    // E+M steps, or the static synthesis of an independent frame
  double energy = 0;          // E_t of the last M-step, per pixel (as OptimizationIteration::energy)
  double keptFraction = 1;    // samples whose source is still the advected one
  double temporalChange = 0;  // mean color change to the previous frame carried along (meanColorChange)
  // Surfaces: whether the solver's repair was kept (false: it would have made the frame flat, and
  // the advected frame was repaired by the surface start's correction instead).
  bool solverKept = true;
};

}  // namespace texsynth
