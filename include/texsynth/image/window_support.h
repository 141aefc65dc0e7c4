#pragma once
// Small helpers shared by the random-access 2D synthesizers (tile-deform, tile-blend):
// option validation and window checks.
#include <cmath>
#include <cstdint>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/image.h"

namespace texsynth {

// Rows per parallel chunk: fixed, so results never depend on the thread count.
inline constexpr std::int64_t kRowChunk = 8;

// Throws ParameterError(name, ...) unless value is finite and >= minimum.
inline void requireFiniteAtLeast(const char* name, float value, float minimum) {
  if (!std::isfinite(value) || value < minimum)
    throw ParameterError(name,
                         "must be a finite number >= " + std::to_string(minimum) + ", got " + std::to_string(value));
}
// Throws ParameterError(name, ...) unless value is finite and > 0.
inline void requireFinitePositive(const char* name, float value) {
  if (!std::isfinite(value) || !(value > 0.0f))
    throw ParameterError(name, "must be a finite number > 0, got " + std::to_string(value));
}

// Throws ParameterError("width" / "height", ...) for an empty window.
inline void requireWindow(int width, int height) {
  if (width <= 0) throw ParameterError("width", "window width must be > 0, got " + std::to_string(width));
  if (height <= 0) throw ParameterError("height", "window height must be > 0, got " + std::to_string(height));
}

}  // namespace texsynth
