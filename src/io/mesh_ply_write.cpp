// PLY writer: binary little endian, float positions and normals, uchar colors when present,
// float vertex attributes ("uv" as s,t as Blender writes them; one component as its name, more as
// NAME_0, NAME_1 ...), triangles as 'list uchar int vertex_indices'.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "mesh_write_support.h"
#include "texsynth/core/error.h"
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

// The PLY property names of each attribute, in map order. Throws ParameterError("mesh", ...) for
// a name that is not one PLY token or that repeats one the file already has.
std::vector<std::pair<const VertexAttribute*, std::vector<std::string>>> attributeProperties(const Mesh& mesh) {
  std::vector<std::string> used = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue"};
  std::vector<std::pair<const VertexAttribute*, std::vector<std::string>>> out;
  for (const auto& [name, attribute] : mesh.attributes) {
    std::vector<std::string> names;
    if (name == kUvAttribute && attribute.components == 2)
      names = {"s", "t"};
    else if (attribute.components == 1)
      names = {name};
    else
      for (int k = 0; k < attribute.components; ++k) names.push_back(name + "_" + std::to_string(k));
    for (const std::string& property : names) {
      const bool token =
          !property.empty() && std::all_of(property.begin(), property.end(), [](char c) { return c > ' ' && c < 127; });
      if (!token) throw ParameterError("mesh", "vertex attribute '" + name + "' is not a PLY property name");
      if (std::find(used.begin(), used.end(), property) != used.end())
        throw ParameterError("mesh",
                             "vertex attribute '" + name + "' would repeat the PLY property '" + property + "'");
      used.push_back(property);
    }
    out.push_back({&attribute, std::move(names)});
  }
  return out;
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
  const auto attributes = attributeProperties(mesh);
  std::size_t attributeFloats = 0;
  for (const auto& [attribute, names] : attributes) {
    for (const std::string& name : names) out += "property float " + name + "\n";
    attributeFloats += names.size();
  }
  out +=
      "element face " + std::to_string(mesh.triangleCount()) + "\nproperty list uchar int vertex_indices\nend_header\n";

  const std::size_t vertexBytes = 24 + (colors ? 3 : 0) + 4 * attributeFloats;
  out.reserve(out.size() + mesh.vertexCount() * vertexBytes + mesh.triangleCount() * 13);
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    for (int k = 0; k < 3; ++k) appendLittle(out, mesh.positions[i][k]);
    for (int k = 0; k < 3; ++k) appendLittle(out, mesh.normals[i][k]);
    if (colors)
      for (int k = 0; k < 3; ++k) appendLittle(out, mesh_detail::colorByte(mesh.colors[i][k]));
    for (const auto& [attribute, names] : attributes)
      for (std::size_t k = 0; k < names.size(); ++k) appendLittle(out, attribute->values[i * names.size() + k]);
  }
  for (const Vec3i& t : mesh.triangles) {
    appendLittle(out, std::uint8_t(3));
    for (int k = 0; k < 3; ++k) appendLittle(out, std::int32_t(t[k]));
  }
  return out;
}

}  // namespace texsynth
