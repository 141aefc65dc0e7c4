#include "texsynth/geometry/surface_voxels.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/geometry/sampling_grid.h"

namespace texsynth {

std::vector<Vec3f> surfaceVoxelCenters(const Mesh& mesh, const Box3f& box, int resolution) {
  const Vec3i n = samplingGridSize(box, resolution);
  if (mesh.triangles.empty()) throw InputError("mesh", "has no triangles");
  const Vec3f voxel = box.size().cwiseQuotient(n.cast<float>());
  const float step = voxel.minCoeff() / 3.0f;
  auto index = [&](const Vec3f& p) -> std::int64_t {
    Vec3i v;
    for (int a = 0; a < 3; ++a) v[a] = std::clamp(int(std::floor((p[a] - box.min[a]) / voxel[a])), 0, n[a] - 1);
    return (std::int64_t(v.z()) * n.y() + v.y()) * n.x() + v.x();
  };
  std::vector<std::int64_t> touched;
  for (const Vec3i& t : mesh.triangles) {
    const Vec3f a = mesh.positions[std::size_t(t[0])], b = mesh.positions[std::size_t(t[1])],
                c = mesh.positions[std::size_t(t[2])];
    // Barycentric lattice with `steps` intervals along the longest edge.
    const float longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int steps = std::max(1, int(std::ceil(longest / step)));
    for (int i = 0; i <= steps; ++i)
      for (int j = 0; i + j <= steps; ++j) {
        const float u = float(i) / steps, v = float(j) / steps;
        touched.push_back(index(a + u * (b - a) + v * (c - a)));
      }
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  std::vector<Vec3f> centres;
  centres.reserve(touched.size());
  for (std::int64_t k : touched) {
    const int x = int(k % n.x()), y = int((k / n.x()) % n.y()), z = int(k / (std::int64_t(n.x()) * n.y()));
    centres.push_back(box.min + Vec3f(x + 0.5f, y + 0.5f, z + 0.5f).cwiseProduct(voxel));
  }
  return centres;
}

}  // namespace texsynth
