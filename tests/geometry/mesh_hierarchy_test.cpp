// The retiled hierarchy: about 4:1 vertices between levels, every vertex's parent triangle and
// weights valid and on the coarser surface, deterministic, and a cached copy equal bit for bit.
#include "texsynth/geometry/mesh_hierarchy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "mesh_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/geometry/mesh_hierarchy_cache.h"

namespace texsynth {
namespace {

MeshHierarchyOptions smallHierarchy() {
  MeshHierarchyOptions options;
  options.vertices = 2400;  // 150, 600, 2400
  return options;
}

void expectSameHierarchy(const MeshHierarchy& a, const MeshHierarchy& b) {
  ASSERT_EQ(a.levels.size(), b.levels.size());
  for (std::size_t l = 0; l < a.levels.size(); ++l) {
    const MeshLevel &x = a.levels[l], &y = b.levels[l];
    EXPECT_EQ(x.mesh.positions, y.mesh.positions) << "level " << l;
    EXPECT_EQ(x.mesh.triangles, y.mesh.triangles) << "level " << l;
    EXPECT_EQ(x.mesh.normals, y.mesh.normals) << "level " << l;
    EXPECT_EQ(x.spacing, y.spacing) << "level " << l;
    EXPECT_EQ(x.parentTriangle, y.parentTriangle) << "level " << l;
    EXPECT_EQ(x.parentBarycentric, y.parentBarycentric) << "level " << l;
  }
}

void expectValidHierarchy(const MeshHierarchy& hierarchy, int levels) {
  ASSERT_EQ(int(hierarchy.levels.size()), levels);
  EXPECT_TRUE(hierarchy.levels[0].parentTriangle.empty());
  EXPECT_TRUE(hierarchy.levels[0].parentBarycentric.empty());
  for (std::size_t l = 0; l < hierarchy.levels.size(); ++l) {
    const MeshLevel& level = hierarchy.levels[l];
    EXPECT_EQ(level.mesh.normals.size(), level.mesh.positions.size());
    EXPECT_NEAR(level.spacing, std::sqrt(level.mesh.surfaceArea() / double(level.mesh.vertexCount())), 1e-4);
    if (l == 0) continue;
    const MeshLevel& coarser = hierarchy.levels[l - 1];
    const double ratio = double(level.mesh.vertexCount()) / double(coarser.mesh.vertexCount());
    EXPECT_GT(ratio, 3.0) << "level " << l;
    EXPECT_LT(ratio, 5.5) << "level " << l;
    ASSERT_EQ(level.parentTriangle.size(), level.mesh.positions.size());
    ASSERT_EQ(level.parentBarycentric.size(), level.mesh.positions.size());
    std::vector<float> distances;
    for (std::size_t v = 0; v < level.mesh.positions.size(); ++v) {
      const int t = level.parentTriangle[v];
      ASSERT_GE(t, 0);
      ASSERT_LT(t, int(coarser.mesh.triangles.size()));
      const Vec3f& w = level.parentBarycentric[v];
      EXPECT_GE(w.minCoeff(), 0.0f);
      EXPECT_NEAR(w.sum(), 1.0f, 1e-5f);
      const Vec3i& tri = coarser.mesh.triangles[std::size_t(t)];
      const Vec3f onParent = w[0] * coarser.mesh.positions[tri[0]] + w[1] * coarser.mesh.positions[tri[1]] +
                             w[2] * coarser.mesh.positions[tri[2]];
      distances.push_back((onParent - level.mesh.positions[v]).norm() / coarser.spacing);
    }
    // Both levels approximate the same surface: fine vertices lie well within a coarse edge of
    // the coarse level, a few more where the coarse level cuts across thin parts (a cow's tail).
    std::sort(distances.begin(), distances.end());
    EXPECT_LT(distances[distances.size() * 95 / 100], 0.35f) << "level " << l;
    EXPECT_LT(distances.back(), 2.0f) << "level " << l;
  }
}

TEST(MeshHierarchy, LevelsFourToOneWithValidParents) {
  const MeshHierarchy hierarchy = buildMeshHierarchy(test::icosphere(3), smallHierarchy(), "icosphere");
  expectValidHierarchy(hierarchy, 3);
  EXPECT_NEAR(double(hierarchy.levels.back().mesh.vertexCount()), 2400, 360);
  EXPECT_GT(hierarchy.seconds, 0);
}

TEST(MeshHierarchy, RealOpenAndClosedMeshes) {
  const std::optional<Mesh> cow = test::demoMesh("cow.off"), pig = test::demoMesh("pig.off");
  TS_REQUIRE_DATA(cow);
  TS_REQUIRE_DATA(pig);
  MeshHierarchyOptions three;
  three.vertices = 4800;  // a 300-vertex cow still has legs
  expectValidHierarchy(buildMeshHierarchy(*cow, three, "cow.off"), 3);
  MeshHierarchyOptions two;
  two.vertices = 2000;
  two.levels = 2;
  expectValidHierarchy(buildMeshHierarchy(*pig, two, "pig.off"), 2);  // pig.off has holes
}

TEST(MeshHierarchy, SameResultTwiceAndForAnyThreadCount) {
  const Mesh sphere = test::irregularSphere(2);
  const MeshHierarchy a = buildMeshHierarchy(sphere, smallHierarchy(), "icosphere");
  const MeshHierarchy b = buildMeshHierarchy(sphere, smallHierarchy(), "icosphere");
  expectSameHierarchy(a, b);
  ThreadLimit one(1);
  expectSameHierarchy(a, buildMeshHierarchy(sphere, smallHierarchy(), "icosphere"));
}

TEST(MeshHierarchy, CachedHierarchyEqualsAFreshOne) {
  test::TempDir cache;
  const Mesh sphere = test::irregularSphere(2);
  const MeshHierarchy fresh = buildMeshHierarchy(sphere, smallHierarchy(), "icosphere");
  const MeshHierarchy first = buildMeshHierarchyCached(sphere, smallHierarchy(), "icosphere", cache.path());
  const std::uint64_t key = meshHierarchyCacheKey(sphere, smallHierarchy());
  const std::string path = meshHierarchyCachePath(cache.path(), key);
  ASSERT_TRUE(std::filesystem::exists(path));
  const std::optional<MeshHierarchy> loaded = loadCachedMeshHierarchy(path, key);
  ASSERT_TRUE(loaded);
  expectSameHierarchy(fresh, first);
  expectSameHierarchy(fresh, *loaded);
  expectSameHierarchy(fresh, buildMeshHierarchyCached(sphere, smallHierarchy(), "icosphere", cache.path()));

  // Another key, a flipped byte or a truncated file is a miss, never trusted.
  const std::string bytes = serializeMeshHierarchy(fresh, key);
  EXPECT_FALSE(deserializeMeshHierarchy(bytes, key + 1));
  std::string corrupted = bytes;
  corrupted[corrupted.size() / 2] ^= 1;
  EXPECT_FALSE(deserializeMeshHierarchy(corrupted, key));
  EXPECT_FALSE(deserializeMeshHierarchy(bytes.substr(0, bytes.size() - 4), key));
  test::writeBytes(path, corrupted);
  expectSameHierarchy(fresh, buildMeshHierarchyCached(sphere, smallHierarchy(), "icosphere", cache.path()));
  EXPECT_TRUE(loadCachedMeshHierarchy(path, key));  // rewritten

  // The key follows the mesh and every option.
  MeshHierarchyOptions other = smallHierarchy();
  other.ratio = 3.5f;
  EXPECT_NE(meshHierarchyCacheKey(sphere, other), key);
  Mesh moved = sphere;
  moved.positions[0].x() += 1e-3f;
  EXPECT_NE(meshHierarchyCacheKey(moved, smallHierarchy()), key);
}

TEST(MeshHierarchy, RejectsBadOptionsAndBadMeshes) {
  const Mesh sphere = test::icosphere(1);
  auto build = [&](int vertices, int levels, float ratio) {
    return [=, &sphere] { buildMeshHierarchy(sphere, {vertices, levels, ratio}, "s.off"); };
  };
  test::expectParameterError(build(0, 3, 4), "vertices");
  test::expectParameterError(build(4000, 0, 4), "levels");
  test::expectParameterError(build(4000, 3, 1), "ratio");
  test::expectParameterError(build(400, 3, 4), "levels");  // 25 vertices at the coarsest level
  Mesh book = sphere;
  book.positions.push_back(Vec3f(3, 3, 3));
  book.normals.push_back(Vec3f::UnitX());
  const Vec3i& t = book.triangles[0];
  book.triangles.push_back({t[1], t[0], int(book.positions.size()) - 1});  // a third face on edge t0-t1
  test::expectInputError([&] { buildMeshHierarchy(book, smallHierarchy(), "book.off"); }, "book.off",
                         "non-manifold edge");
}

}  // namespace
}  // namespace texsynth
