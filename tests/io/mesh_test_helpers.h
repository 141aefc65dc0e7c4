#pragma once
// Small meshes and encoders shared by the mesh I/O tests.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>

#include "texsynth/core/mesh.h"

namespace texsynth::test {

// A unit cube: 8 vertices, 12 outward triangles, distinct vertex colors.
inline Mesh makeColoredCube() {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.positions.emplace_back(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
    mesh.colors.emplace_back(0.1f * float(i), 1.0f - 0.1f * float(i), 0.5f);
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.emplace_back(q[0], q[1], q[2]);
    mesh.triangles.emplace_back(q[0], q[2], q[3]);
  }
  mesh.computeNormals();
  return mesh;
}

// Appends a value in the requested byte order.
template <class T>
void appendBytes(std::string& out, T value, bool bigEndian = false) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (bigEndian != (std::endian::native == std::endian::big))
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(raw), sizeof(T));
}

// Binary STL: one record per triangle, corners duplicated as STL does.
inline std::string encodeBinaryStl(const Mesh& mesh) {
  std::string out(80, ' ');
  out.replace(0, 12, "binary test ");
  appendBytes(out, std::uint32_t(mesh.triangleCount()));
  for (const Vec3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) appendBytes(out, 0.0f);  // stored normal (ignored by readers)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) appendBytes(out, mesh.positions[t[c]][k]);
    appendBytes(out, std::uint16_t(0));
  }
  return out;
}

inline std::string encodeAsciiStl(const Mesh& mesh) {
  std::string out = "solid test\n";
  for (const Vec3i& t : mesh.triangles) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (int c = 0; c < 3; ++c) {
      const Vec3f& p = mesh.positions[t[c]];
      out += "      vertex " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid test\n";
}

}  // namespace texsynth::test
