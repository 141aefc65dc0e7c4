#pragma once
// Built-in stand-ins for the demo when the real data packages (gimp-data, libcgal-demo) are absent.
#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"

namespace texsynth::cli {

// A veined, marble-like RGB texture from hashed value noise (deterministic, tileable).
Image proceduralMarble(int size, std::uint64_t seed);
// A unit icosphere subdivided `subdivisions` times.
Mesh icosphere(int subdivisions);

}  // namespace texsynth::cli
