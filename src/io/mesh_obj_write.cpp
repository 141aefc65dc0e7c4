// OBJ writer: 'v x y z [r g b]', 'vt u v' (the "uv" attribute, if any), 'vn nx ny nz' and
// 'f a/[a]/a b/[b]/b c/[c]/c' (1-based). Numbers are written in their shortest exact form, so
// positions read back bit-identical.
#include "mesh_write_support.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {

std::string encodeObj(const Mesh& input) {
  Mesh storage;
  const Mesh& mesh = mesh_detail::preparedForWriting(input, storage);
  const bool colors = !mesh.colors.empty();
  std::string out = "# written by texsynth\n";
  out.reserve(mesh.vertexCount() * (colors ? 96 : 64) + mesh.triangleCount() * 40);
  auto appendVector = [&](const char* keyword, const Vec3f& v) {
    out += keyword;
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      mesh_detail::appendFloat(out, v[k]);
    }
  };
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    appendVector("v", mesh.positions[i]);
    if (colors)
      for (int k = 0; k < 3; ++k) {
        out += ' ';
        mesh_detail::appendFloat(out, mesh.colors[i][k]);
      }
    out += '\n';
  }
  const auto uv = mesh.attributes.find(kUvAttribute);
  const bool uvs = uv != mesh.attributes.end() && uv->second.components == 2;
  if (uvs)
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
      out += "vt ";
      mesh_detail::appendFloat(out, uv->second.values[2 * i]);
      out += ' ';
      mesh_detail::appendFloat(out, uv->second.values[2 * i + 1]);
      out += '\n';
    }
  for (const Vec3f& n : mesh.normals) {
    appendVector("vn", n);
    out += '\n';
  }
  for (const Vec3i& t : mesh.triangles) {
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      mesh_detail::appendInt(out, t[k] + 1);
      out += '/';
      if (uvs) mesh_detail::appendInt(out, t[k] + 1);
      out += '/';
      mesh_detail::appendInt(out, t[k] + 1);
    }
    out += '\n';
  }
  return out;
}

}  // namespace texsynth
