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

// Tile-deform's clamp on corner displacements, as a fraction of the cell (2D and 3D alike): below
// one half, neighbouring corners can never meet, so cells never fold.
inline void requireDeformationClamp(const char* name, float clamp) {
  if (!(clamp >= 0.0f && clamp < 0.5f))
    throw ParameterError(
        name, "must be in [0, 0.5) of the cell (from 0.5 on, deformed cells can fold), got " + std::to_string(clamp));
}

// Every random-access method's windows stay within +-2^28 pixels of the origin: parallel
// synthesis does its coordinate arithmetic in 32 bits (with room for the coarser levels' spacing),
// and tile-deform and tile-blend place pixel centres in doubles and cell fractions in floats,
// which stop resolving single pixels (giving stripes of repeated columns) far beyond that.
inline constexpr std::int64_t kMaxWindowCoordinate = std::int64_t(1) << 28;

// Throws ParameterError("width" / "height", ...) for an empty window, ("x0" / "y0", ...) for one
// reaching beyond +-kMaxWindowCoordinate.
inline void requireWindow(std::int64_t x0, std::int64_t y0, int width, int height) {
  if (width <= 0) throw ParameterError("width", "window width must be > 0, got " + std::to_string(width));
  if (height <= 0) throw ParameterError("height", "window height must be > 0, got " + std::to_string(height));
  const std::string beyondReach =
      "the window must stay within +-2^28 pixels of the origin, where every method still tells neighbouring pixels "
      "apart";
  const auto outside = [](std::int64_t start, int size) {
    return start <= -kMaxWindowCoordinate || start >= kMaxWindowCoordinate - size;
  };
  if (outside(x0, width)) throw ParameterError("x0", beyondReach + ", got x0 = " + std::to_string(x0));
  if (outside(y0, height)) throw ParameterError("y0", beyondReach + ", got y0 = " + std::to_string(y0));
}

}  // namespace texsynth
