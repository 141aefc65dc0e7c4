#pragma once
// Internal to gradient synthesis: histogram matching of the control points (Kopf et al. 2007 keep solid
// texture optimization from washing out the same way). Averaging the samples of many patches pulls every
// voxel towards the mean, and nearest patches to a low-contrast solid are low-contrast ones; without a
// counterweight the optimization converges to flat colour (measured: brick at 64^3 ends at 15% of the
// exemplar's standard deviation). After each iteration every channel's control values are mapped onto the
// exemplar level's distribution by a smooth monotone transfer, and the gradients scaled by its slope (the
// negative-side sets of a solid with regions go with the positive ones; residual detail is left as it is).
#include "texsynth/core/image.h"
#include "texsynth/gradient/gradient_solid.h"

namespace texsynth::gradient_synthesis {

void matchControlHistograms(GradientSolid& state, const Image& target);

}  // namespace texsynth::gradient_synthesis
