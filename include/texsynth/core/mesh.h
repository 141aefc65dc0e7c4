#pragma once
// Mesh: indexed triangles with per-vertex normals, optional colors and named attributes.
#include <map>
#include <string>
#include <vector>

#include "texsynth/core/math.h"

namespace texsynth {

// A per-vertex attribute with a fixed number of float components per vertex. The readers keep
// texture coordinates as "uv" (2 components, v up as in OBJ and PLY) and every other scalar PLY
// vertex property under its own name (1 component).
inline constexpr const char* kUvAttribute = "uv";

struct VertexAttribute {
  int components = 1;
  std::vector<float> values;  // size vertexCount*components
};

struct Mesh {
  std::vector<Vec3f> positions;
  std::vector<Vec3i> triangles;
  std::vector<Vec3f> normals;  // per vertex; empty until computeNormals() or loaded
  std::vector<Vec3f> colors;   // per vertex, [0,1]; empty if none
  std::map<std::string, VertexAttribute> attributes;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
  Box3f bounds() const;
  // Area-weighted vertex normals (outward for a consistently oriented closed mesh).
  void computeNormals();
  // Throws InputError(source, ...) if indices are out of range, coordinates not finite, or a
  // per-vertex array (normals, colors, an attribute) does not match the vertex count.
  void validate(const std::string& source) const;
  double surfaceArea() const;
};

}  // namespace texsynth
