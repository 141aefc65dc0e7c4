#pragma once
// Built-in stand-in for the demo when gimp-data is absent (the mesh stand-in is render's sphere).
#include <cstdint>

#include "texsynth/core/image.h"

namespace texsynth::cli {

// A veined, marble-like RGB texture from hashed value noise (deterministic, tileable).
Image proceduralMarble(int size, std::uint64_t seed);

}  // namespace texsynth::cli
