#pragma once
// Shared pieces of the mesh writers. Internal to the io module.
#include <cstdint>
#include <string>

#include "texsynth/core/mesh.h"

namespace texsynth::mesh_detail {

// Checks that the mesh is consistent (throws ParameterError("mesh", ...) if not) and returns
// it, or, when it has no normals, a copy in `storage` with normals computed.
const Mesh& preparedForWriting(const Mesh& mesh, Mesh& storage);

// A [0,1] color component as a byte, rounded; values outside [0,1] saturate.
std::uint8_t colorByte(float value);

// Appends the shortest decimal text that reads back as exactly `value`.
void appendFloat(std::string& out, float value);
void appendInt(std::string& out, int value);

}  // namespace texsynth::mesh_detail
