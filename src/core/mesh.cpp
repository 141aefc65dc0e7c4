#include "texsynth/core/mesh.h"

#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {

Box3f Mesh::bounds() const {
  Box3f box;
  for (const Vec3f& p : positions) box.extend(p);
  return box;
}

void Mesh::computeNormals() {
  normals.assign(positions.size(), Vec3f::Zero());
  for (const Vec3i& t : triangles) {
    // Cross product length is twice the area: area weighting for free.
    Vec3f n = (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]);
    for (int k = 0; k < 3; ++k) normals[t[k]] += n;
  }
  for (Vec3f& n : normals) {
    float len = n.norm();
    n = len > 0 ? Vec3f(n / len) : Vec3f::UnitZ();
  }
}

void Mesh::validate(const std::string& source) const {
  if (positions.empty()) throw InputError(source, "mesh has no vertices");
  if (triangles.empty()) throw InputError(source, "mesh has no faces");
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!positions[i].allFinite())
      throw InputError(source, "vertex " + std::to_string(i) + " has a non-finite coordinate");
  const int n = int(positions.size());
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (triangles[i][k] < 0 || triangles[i][k] >= n)
        throw InputError(source, "face " + std::to_string(i) + " refers to vertex " + std::to_string(triangles[i][k]) +
                                     " but the mesh has " + std::to_string(n) + " vertices");
  if (!normals.empty() && normals.size() != positions.size())
    throw InputError(source, "normal count differs from vertex count");
  if (!colors.empty() && colors.size() != positions.size())
    throw InputError(source, "color count differs from vertex count");
  for (const auto& [name, attribute] : attributes)
    if (attribute.components < 1 || attribute.values.size() != positions.size() * std::size_t(attribute.components))
      throw InputError(source, "vertex attribute '" + name + "' has " + std::to_string(attribute.values.size()) +
                                   " values for " + std::to_string(positions.size()) + " vertices");
}

double Mesh::surfaceArea() const {
  double area = 0;
  for (const Vec3i& t : triangles)
    area += 0.5 * double((positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]).norm());
  return area;
}

}  // namespace texsynth
