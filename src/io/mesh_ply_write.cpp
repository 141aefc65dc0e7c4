// PLY writer: binary little endian, float positions and normals, uchar colors when present,
// triangles as 'list uchar int vertex_indices'.
#include <bit>
#include <cmath>
#include <cstring>

#include "mesh_write_support.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {

// Appends a value in little-endian byte order whatever the host's order.
template <class T>
void appendLittle(std::string& out, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(raw), sizeof(T));
}

}  // namespace

std::string encodePly(const Mesh& input) {
  Mesh storage;
  const Mesh& mesh = mesh_detail::preparedForWriting(input, storage);
  const bool colors = !mesh.colors.empty();
  std::string out =
      "ply\nformat binary_little_endian 1.0\ncomment written by texsynth\n"
      "element vertex " +
      std::to_string(mesh.vertexCount()) +
      "\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\n";
  if (colors) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out +=
      "element face " + std::to_string(mesh.triangleCount()) + "\nproperty list uchar int vertex_indices\nend_header\n";

  const std::size_t vertexBytes = 24 + (colors ? 3 : 0);
  out.reserve(out.size() + mesh.vertexCount() * vertexBytes + mesh.triangleCount() * 13);
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    for (int k = 0; k < 3; ++k) appendLittle(out, mesh.positions[i][k]);
    for (int k = 0; k < 3; ++k) appendLittle(out, mesh.normals[i][k]);
    if (colors)
      for (int k = 0; k < 3; ++k) appendLittle(out, mesh_detail::colorByte(mesh.colors[i][k]));
  }
  for (const Vec3i& t : mesh.triangles) {
    appendLittle(out, std::uint8_t(3));
    for (int k = 0; k < 3; ++k) appendLittle(out, std::int32_t(t[k]));
  }
  return out;
}

}  // namespace texsynth
