#pragma once
// The bounds every flow shares, image and surface alike, and the check of a flow SPEC that needs
// no output size or mesh: what the command line runs while it parses --flow, before any work.
#include <string>

namespace texsynth {

// Largest velocity component anywhere: a preset's strength, dx or dy (pixels or vertex spacings per
// frame) and every value of a velocity file (pixels or world units per frame). Farther than this
// in one frame is no flow but noise.
inline constexpr float kMaxFlowSpeed = 4096.0f;
// Largest |scale| (--flow-scale), so no scaled velocity can overflow.
inline constexpr float kMaxFlowScale = 64.0f;

// Throws ParameterError("flowScale", ...) unless |scale| <= kMaxFlowScale and finite.
void requireFlowScale(float scale);

// Checks SPEC as ImageFlow::parse and SurfaceFlow::parse would, against the presets of both:
// the preset's keys and each value's range, or a well-formed frame pattern for a file. Files are
// not opened. Throws ParameterError("flow", ...).
void checkFlowSpecification(const std::string& spec);

}  // namespace texsynth
