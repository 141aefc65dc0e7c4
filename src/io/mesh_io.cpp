// readMesh / writeMesh: pick the format by extension, finish what every reader shares
// (validation, normals) and write atomically.
#include "texsynth/io/mesh_io.h"

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/io/readable_file.h"

namespace texsynth {
namespace {

// Mesh files past this size are rejected before reading (the largest CGAL demo mesh is 3 MB).
constexpr std::size_t kMaxMeshFileBytes = std::size_t(2) << 30;

}  // namespace

Mesh readMesh(const std::string& path) {
  requireReadableFile(path);  // a missing file or a directory is that, not an unsupported format
  const std::string extension = fileExtension(path);
  Mesh (*parse)(std::string_view, const std::string&) = nullptr;
  if (extension == "obj")
    parse = parseObj;
  else if (extension == "ply")
    parse = parsePly;
  else if (extension == "off")
    parse = parseOff;
  else if (extension == "stl")
    parse = parseStl;
  else if (extension == "glb" || extension == "gltf")
    parse = parseGltf;
  else
    throw InputError(path, "unsupported mesh format '." + extension + "' (readable: .obj .ply .off .stl .glb .gltf)");

  const std::string bytes = readFileBytes(path, kMaxMeshFileBytes);
  Mesh mesh = parse(bytes, path);
  mesh.validate(path);
  if (mesh.normals.empty()) mesh.computeNormals();
  return mesh;
}

void writeMesh(const std::string& path, const Mesh& mesh) {
  const std::string extension = fileExtension(path);
  std::string bytes;
  if (extension == "ply")
    bytes = encodePly(mesh);
  else if (extension == "obj")
    bytes = encodeObj(mesh);
  else if (extension == "glb")
    bytes = encodeGltf(mesh, true);
  else if (extension == "gltf")
    bytes = encodeGltf(mesh, false);
  else
    throw ParameterError(path, "unsupported mesh output format '." + extension + "' (writable: .ply .obj .glb .gltf)");
  writeFileAtomically(path, bytes);
}

}  // namespace texsynth
