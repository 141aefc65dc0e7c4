#pragma once
// A surface synthesis stored on its mesh: each vertex's exemplar pixel as two float vertex
// attributes, source_u = (x + 0.5) / W and source_v = (y + 0.5) / H (PLY properties of the same
// names). Normalized, so the synthesis can be re-applied to another map of the same material at
// another resolution: a vertex reads the pixel of that map that covers the same spot.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "texsynth/core/mesh.h"

namespace texsynth {

inline constexpr const char* kSourceUAttribute = "source_u";
inline constexpr const char* kSourceVAttribute = "source_v";

// Adds (or replaces) the two attributes on `mesh`, one source (y * width + x) per vertex. Throws
// ParameterError("sources", ...) for a count that is not the mesh's vertex count or a source
// outside the exemplar, ParameterError("width" / "height", ...) for a size below 1.
void storeSourceCoordinates(Mesh& mesh, std::span<const std::int32_t> sources, int width, int height);

// The sources of a stored synthesis in an exemplar of width x height (the pixel containing each
// (u, v); for the exemplar it was synthesized from, exactly the stored ones). Throws
// InputError(source, ...) for a mesh without both attributes or with a value that is not in
// [0, 1], ParameterError("width" / "height", ...) for a size below 1.
std::vector<std::int32_t> sourcesFromCoordinates(const Mesh& mesh, int width, int height, const std::string& source);

}  // namespace texsynth
