#include "texsynth/render/primitives.h"

#include <gtest/gtest.h>

#include <numbers>

#include "texsynth/core/error.h"

using namespace texsynth;

namespace {

// Every face must be non-degenerate, wind counter-clockwise seen from outside (its normal
// points away from `inside`) and agree with its vertices' normals.
void expectOutwardAndConsistent(const Mesh& mesh, const Vec3f& inside) {
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  EXPECT_NO_THROW(mesh.validate("primitive"));
  for (const Vec3i& t : mesh.triangles) {
    const Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const Vec3f faceNormal = (b - a).cross(c - a);
    ASSERT_GT(faceNormal.norm(), 1e-8f);
    EXPECT_GT(faceNormal.dot((a + b + c) / 3 - inside), 0);
    for (int k = 0; k < 3; ++k) EXPECT_GT(faceNormal.normalized().dot(mesh.normals[t[k]]), 0.5f);
  }
}

}  // namespace

TEST(Primitives, BoxIsClosedWithOutwardFaces) {
  const Mesh box = makeBoxMesh(Vec3f(-1, 0, 2), Vec3f(3, 1, 4));
  EXPECT_EQ(box.vertexCount(), 24u);
  EXPECT_EQ(box.triangleCount(), 12u);
  EXPECT_NEAR(box.surfaceArea(), 2 * (4 * 1 + 4 * 2 + 1 * 2), 1e-4);
  EXPECT_TRUE(box.bounds().min.isApprox(Vec3f(-1, 0, 2)));
  EXPECT_TRUE(box.bounds().max.isApprox(Vec3f(3, 1, 4)));
  expectOutwardAndConsistent(box, Vec3f(1, 0.5f, 3));
}

TEST(Primitives, UvSphereApproximatesTheSphere) {
  const Vec3f center(1, 2, 3);
  const Mesh sphere = makeUvSphereMesh(center, 2, 24, 48);
  EXPECT_EQ(sphere.triangleCount(), std::size_t(2 * 48 * (24 - 1)));
  for (const Vec3f& p : sphere.positions) EXPECT_NEAR((p - center).norm(), 2, 1e-5);
  EXPECT_NEAR(sphere.surfaceArea(), 4 * std::numbers::pi * 4, 0.02 * 4 * std::numbers::pi * 4);
  expectOutwardAndConsistent(sphere, center);
}

TEST(Primitives, BadParametersThrow) {
  EXPECT_THROW(makeBoxMesh(Vec3f::Ones(), Vec3f::Zero()), ParameterError);
  EXPECT_THROW(makeUvSphereMesh(Vec3f::Zero(), 0, 8, 8), ParameterError);
  EXPECT_THROW(makeUvSphereMesh(Vec3f::Zero(), 1, 1, 8), ParameterError);
  EXPECT_THROW(makeUvSphereMesh(Vec3f::Zero(), 1, 8, 2), ParameterError);
}
