#include "texsynth/solid/solid_consumers.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

// One expression for every grid coordinate, so slices and volume planes agree bit for bit.
float gridCoordinate(const Box3f& box, int axis, float fraction) {
  return box.min[axis] + fraction * box.size()[axis];
}

float voxelFraction(int index, int count) {
  return (float(index) + 0.5f) / float(count);
}

// The two in-plane axes of a slice normal to `axis`, in image (u, v) order.
std::pair<int, int> sliceAxes(int axis) {
  if (axis == 0) return {1, 2};
  if (axis == 1) return {0, 2};
  return {0, 1};
}

}  // namespace

void colorMeshVertices(Mesh& mesh, const SolidTexture& solid) {
  mesh.validate("mesh");
  if (mesh.normals.size() != mesh.positions.size()) mesh.computeNormals();
  mesh.colors = solid.evaluateColors(mesh.positions, mesh.normals);
}

SurfaceColorFunction surfaceColorFunction(const SolidTexture& solid) {
  return [&solid](const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals, std::vector<Vec3f>& colors) {
    colors = solid.evaluateColors(points, normals);
  };
}

Image sampleSlice(const SolidTexture& solid, const Box3f& box, int axis, float position, int resolution) {
  if (axis < 0 || axis > 2) throw ParameterError("axis", "must be 0 (x), 1 (y) or 2 (z)");
  if (!(position >= 0.0f && position <= 1.0f)) throw ParameterError("position", "must be in [0, 1]");
  const Vec3i grid = samplingGridSize(box, resolution);
  const auto [uAxis, vAxis] = sliceAxes(axis);
  const int width = grid[uAxis], height = grid[vAxis];
  std::vector<Vec3f> points(std::size_t(width) * height);
  for (int v = 0; v < height; ++v)
    for (int u = 0; u < width; ++u) {
      Vec3f& p = points[std::size_t(v) * width + u];
      p[axis] = gridCoordinate(box, axis, position);
      p[uAxis] = gridCoordinate(box, uAxis, voxelFraction(u, width));
      p[vAxis] = gridCoordinate(box, vAxis, voxelFraction(v, height));
    }
  Image image(width, height, solid.channels());
  solid.evaluate(points, {}, image.pixels);
  return image;
}

Volume sampleVolume(const SolidTexture& solid, const Box3f& box, int resolution) {
  const Vec3i grid = samplingGridSize(box, resolution);
  Volume volume(grid.x(), grid.y(), grid.z(), solid.channels());
  const std::size_t slab = std::size_t(grid.x()) * grid.y();
  parallelFor(0, grid.z(), [&](std::int64_t z) {
    std::vector<Vec3f> points(slab);
    const float pz = gridCoordinate(box, 2, voxelFraction(int(z), grid.z()));
    for (int y = 0; y < grid.y(); ++y)
      for (int x = 0; x < grid.x(); ++x)
        points[std::size_t(y) * grid.x() + x] = Vec3f(gridCoordinate(box, 0, voxelFraction(x, grid.x())),
                                                      gridCoordinate(box, 1, voxelFraction(y, grid.y())), pz);
    solid.evaluateSerial(points, {}, std::span<float>(volume.voxel(0, 0, int(z)), slab * volume.channels));
  });
  return volume;
}

}  // namespace texsynth
