#include <algorithm>
#include <cmath>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth {

namespace {

void requireFinite(const char* name, float value) {
  if (!std::isfinite(value)) throw ParameterError(name, "must be finite");
}

void requireRange(const char* name, int value, int low, int high) {
  if (value < low || value > high)
    throw ParameterError(
        name, "must be in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " + std::to_string(value));
}

}  // namespace

void validateRenderOptions(const RenderOptions& options) {
  requireRange("width", options.width, 1, 16384);
  requireRange("height", options.height, 1, 16384);
  requireRange("supersample", options.supersample, 1, 16);
  // The supersampled grid is held in memory (about 50 bytes per sample at most).
  if (std::max(options.width, options.height) * options.supersample > 16384)
    throw ParameterError("supersample", "width and height times supersample must not exceed 16384, got " +
                                            std::to_string(std::max(options.width, options.height)) + " x " +
                                            std::to_string(options.supersample));
  requireFinite("yawDegrees", options.yawDegrees);
  requireFinite("pitchDegrees", options.pitchDegrees);
  if (!options.up.allFinite() || !(options.up.cwiseAbs().maxCoeff() > 0))
    throw ParameterError("up", "must be a finite non-zero vector");
  if (!(options.fovDegrees > 0 && options.fovDegrees < 170))
    throw ParameterError("fovDegrees", "must be in (0, 170), got " + std::to_string(options.fovDegrees));
  if (!(options.margin >= 0 && std::isfinite(options.margin)))
    throw ParameterError("margin", "must be finite and >= 0, got " + std::to_string(options.margin));
  if (!(options.ambient >= 0 && options.ambient <= 1))
    throw ParameterError("ambient", "must be in [0, 1], got " + std::to_string(options.ambient));
  if (!options.lightDirection.allFinite() || options.lightDirection.squaredNorm() == 0)
    throw ParameterError("lightDirection", "must be a finite non-zero vector");
  if (!options.background.allFinite()) throw ParameterError("background", "must be a finite colour");
  if (!options.defaultColor.allFinite()) throw ParameterError("defaultColor", "must be a finite colour");
}

}  // namespace texsynth
