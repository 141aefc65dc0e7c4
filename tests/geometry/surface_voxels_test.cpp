// Surface voxels: a box's surface covers exactly the grid's outer shell of voxels.
#include "texsynth/geometry/surface_voxels.h"

#include <gtest/gtest.h>

#include <tuple>

#include "texsynth/core/error.h"
#include "texsynth/render/primitives.h"

namespace texsynth {
namespace {

TEST(SurfaceVoxels, ABoxCoversTheOuterShellOfItsGrid) {
  Mesh box = makeBoxMesh(Vec3f::Zero(), Vec3f(2, 2, 2));
  const int n = 8;
  std::vector<Vec3f> centres = surfaceVoxelCenters(box, box.bounds(), n);
  EXPECT_EQ(centres.size(), std::size_t(n * n * n - (n - 2) * (n - 2) * (n - 2)));  // the shell
  for (const Vec3f& c : centres) {
    const Vec3f cell = c / 0.25f - Vec3f::Constant(0.5f);  // voxel index
    EXPECT_TRUE(cell.minCoeff() < 0.5f || cell.maxCoeff() > n - 1.5f) << c.transpose();
  }
  EXPECT_TRUE(std::is_sorted(centres.begin(), centres.end(), [](const Vec3f& a, const Vec3f& b) {
    return std::make_tuple(a.z(), a.y(), a.x()) < std::make_tuple(b.z(), b.y(), b.x());
  }));
}

TEST(SurfaceVoxels, RejectsAnEmptyMesh) {
  Box3f unit;
  unit.extend(Vec3f::Zero());
  unit.extend(Vec3f::Ones());
  EXPECT_THROW(surfaceVoxelCenters(Mesh{}, unit, 4), InputError);
}

}  // namespace
}  // namespace texsynth
