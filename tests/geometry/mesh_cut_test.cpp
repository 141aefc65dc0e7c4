// Cutting a mesh open: the kept side, a cap exactly where the plane is inside, bad arguments.
#include "texsynth/geometry/mesh_cut.h"

#include <gtest/gtest.h>

#include "test_support.h"
#include "texsynth/render/glyph_mesh.h"
#include "texsynth/render/primitives.h"

namespace texsynth {
namespace {

TEST(MeshCut, KeepsTheLowSideAndCapsTheInside) {
  const Mesh box = coloredCopy(makeBoxMesh(Vec3f::Zero(), Vec3f(2, 1, 1)), Vec3f(0.5f, 0.5f, 0.5f));
  const MeshCut cut = cutOpenMesh(box, 0, 0.25f, 0.1f, Vec3f(1, 0, 0));
  EXPECT_FLOAT_EQ(cut.offset, 0.5f);
  EXPECT_EQ(cut.normal, Vec3f::UnitX());
  // The plane x = 0.5 crosses the box's 1 x 1 section: 10 x 10 cells of 0.1, all inside.
  ASSERT_EQ(cut.cells.size(), 100u);
  for (const auto& cell : cut.cells) {
    EXPECT_FLOAT_EQ(cell.centre.x(), 0.5f);
    EXPECT_GT(cell.centre.y(), 0.0f);
    EXPECT_LT(cell.centre.z(), 1.0f);
  }
  // Kept box triangles lie on the low side; each cap square adds two red triangles.
  const Mesh kept = clipMesh(box, Vec3f::UnitX(), 0.5f);
  EXPECT_EQ(cut.mesh.triangles.size(), kept.triangles.size() + 2 * cut.cells.size());
  EXPECT_EQ(cut.mesh.colors.back(), Vec3f(1, 0, 0));

  test::expectParameterError([&] { cutOpenMesh(box, 3, 0.5f, 0.1f, Vec3f::Ones()); }, "cutAxis");
  test::expectParameterError([&] { cutOpenMesh(box, 0, 1.0f, 0.1f, Vec3f::Ones()); }, "cutPosition");
  test::expectParameterError([&] { cutOpenMesh(box, 0, 0.5f, 0.0f, Vec3f::Ones()); }, "capCell");
  test::expectParameterError(
      [&] { cutOpenMesh(makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()), 0, 0.5f, 0.1f, Vec3f::Ones()); }, "mesh");
}

}  // namespace
}  // namespace texsynth
