#include "mesh_write_support.h"

#include <charconv>
#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth::mesh_detail {

const Mesh& preparedForWriting(const Mesh& mesh, Mesh& storage) {
  try {
    mesh.validate("mesh");
  } catch (const InputError& error) {
    // A bad mesh handed to a writer is the caller's mistake, not a bad file.
    throw ParameterError("mesh", error.problem());
  }
  if (!mesh.normals.empty()) return mesh;
  storage = mesh;
  storage.computeNormals();
  return storage;
}

std::uint8_t colorByte(float value) {
  if (!(value > 0.0f)) return 0;  // also maps NaN to 0
  if (value >= 1.0f) return 255;
  return std::uint8_t(std::lround(value * 255.0f));
}

void appendFloat(std::string& out, float value) {
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

void appendInt(std::string& out, int value) {
  char buffer[16];
  auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

}  // namespace texsynth::mesh_detail
