// Mesh readers (OBJ, PLY, OFF, STL). Every input goes through all four parsers (each rejects a
// wrong header quickly), then through what readMesh does next: validation and normals.
// Bad input must raise InputError; anything else escaping is a bug.
#include <string_view>

#include "one_thread.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (auto parse : {texsynth::parseObj, texsynth::parsePly, texsynth::parseOff, texsynth::parseStl}) {
    try {
      texsynth::Mesh mesh = parse(bytes, "fuzz input");
      mesh.validate("fuzz input");
      if (mesh.normals.empty()) mesh.computeNormals();
    } catch (const texsynth::InputError&) {
    }
  }
  return 0;
}
