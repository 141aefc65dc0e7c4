#pragma once
// The instant edit of §4.4 at the paper's size: a 512^3-equivalent gradient solid (129^3 control points)
// against the same edit voxel by voxel on the 512^3 raster, both timed in the same run.
#include "texsynth/gradient/gradient_solid.h"

namespace texsynth::bench {

// Magnifies `solid` 4x into a 512^3-equivalent solid (the paper's edit size), edits it and its raster
// with the same strokes, and prints a Markdown table.
void printEditSpeeds(const GradientSolid& solid, int repeats = 3);

}  // namespace texsynth::bench
