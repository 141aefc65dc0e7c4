#include "texsynth/render/view_up.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render_test_helpers.h"
#include "test_support.h"
#include "texsynth/render/primitives.h"
#include "texsynth/render/render_mesh.h"

using namespace texsynth;

namespace {

// A square pyramid standing on its base (y = 0, x and z in [-1, 1]) with its apex at y = 3:
// it stands on its -Y face only (the other faces of its box touch an edge or the apex).
Mesh pyramid() {
  Mesh mesh;
  mesh.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 3, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 4, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 0}};
  return mesh;
}

Mesh transformed(Mesh mesh, const Mat3f& rotation) {
  for (Vec3f& p : mesh.positions) p = rotation * p;
  return mesh;
}

// A quarter-turn rotation (a signed permutation, exact in floats) that takes +Y to `up`.
Mat3f quarterTurnTo(const Vec3f& up) {
  const Mat3f frame = upFrame(up);
  return frame.array().round().matrix();
}

const Vec3f kAxisDirections[6] = {Vec3f::UnitY(),  Vec3f::UnitZ(),  Vec3f::UnitX(),
                                  -Vec3f::UnitY(), -Vec3f::UnitZ(), -Vec3f::UnitX()};

}  // namespace

TEST(ViewUp, FootprintIsTheBaseBelowAndNothingOnTheOtherFaces) {
  const Mesh mesh = pyramid();
  EXPECT_FLOAT_EQ(floorFootprint(mesh, 1, true), 1.0f);   // the base fills the box's -Y face
  EXPECT_FLOAT_EQ(floorFootprint(mesh, 1, false), 0.0f);  // the apex
  for (int axis : {0, 2})
    for (bool positive : {true, false}) EXPECT_LT(floorFootprint(mesh, axis, positive), 0.05f);  // an edge
  EXPECT_EQ(floorFootprint(Mesh{}, 1, true), 0.0f);
  test::expectParameterError([&] { floorFootprint(mesh, 3, true); }, "axis");
}

// A floor leaning a little (feet not quite level) still counts; a steep one does not.
TEST(ViewUp, FootprintAllowsASlightlyLeaningFloor) {
  Mesh mesh = pyramid();
  const float slope = std::tan(2.0f * std::numbers::pi_v<float> / 180);  // 2 degrees: within kFloorTilt
  for (int i = 0; i < 4; ++i) mesh.positions[std::size_t(i)].y() += slope * (mesh.positions[std::size_t(i)].x() + 1);
  EXPECT_GT(floorFootprint(mesh, 1, true), 0.9f);
  for (int i = 0; i < 4; ++i) mesh.positions[std::size_t(i)].y() *= 10;  // about 19 degrees
  EXPECT_LT(floorFootprint(mesh, 1, true), 0.6f);
}

// Turned by quarter turns, the pyramid's up turns alike: -Z, +X, ... up come out as such.
TEST(ViewUp, UpFollowsTheFloorTheMeshStandsOn) {
  for (const Vec3f& up : kAxisDirections) {
    const Mat3f turn = quarterTurnTo(up);
    ASSERT_TRUE((turn * Vec3f::UnitY()).isApprox(up));
    EXPECT_EQ(viewUpDirection(transformed(pyramid(), turn)), up) << up.transpose();
  }
}

// Meshes without a floor, or standing equally on every face, keep +Y.
TEST(ViewUp, KeepsPlusYWithoutAClearFloor) {
  EXPECT_EQ(viewUpDirection(makeUvSphereMesh(Vec3f(1, 2, 3), 2.0f, 24, 48)), Vec3f::UnitY());
  EXPECT_EQ(viewUpDirection(makeBoxMesh(Vec3f(0, 0, 0), Vec3f(4, 1, 2))), Vec3f::UnitY());
  EXPECT_EQ(viewUpDirection(Mesh{}), Vec3f::UnitY());
  // A pyramid turned to no axis touches no face of its box over a real area.
  const Mat3f oblique = Eigen::AngleAxisf(0.6f, Vec3f(1, 0.3f, 0.5f).normalized()).toRotationMatrix();
  EXPECT_EQ(viewUpDirection(transformed(pyramid(), oblique)), Vec3f::UnitY());
}

TEST(ViewUp, UpFrameTakesPlusYToUp) {
  EXPECT_EQ(upFrame(Vec3f::UnitY()), Mat3f::Identity());
  EXPECT_EQ(upFrame(Vec3f(0, 5, 0)), Mat3f::Identity());
  for (const Vec3f& up : {Vec3f(0, -1, 0), Vec3f(0, 0, 1), Vec3f(-1, 0, 0), Vec3f(1, 2, -3), Vec3f(1e-4f, -1, 0)}) {
    const Mat3f frame = upFrame(up);
    EXPECT_TRUE((frame * Vec3f::UnitY()).isApprox(up.normalized(), 1e-5f)) << up.transpose();
    EXPECT_TRUE((frame.transpose() * frame).isApprox(Mat3f::Identity(), 1e-5f));
    EXPECT_NEAR(frame.determinant(), 1.0f, 1e-5f);
  }
  EXPECT_TRUE(upFrame(-Vec3f::UnitY()).isApprox(Vec3f(1, -1, -1).asDiagonal().toDenseMatrix()));
  test::expectParameterError([] { upFrame(Vec3f::Zero()); }, "up");
}

// anglesAboutUp keeps the camera where (yaw, pitch) about +Y puts it.
TEST(ViewUp, AnglesAboutUpKeepTheViewingDirection) {
  auto eye = [](float yaw, float pitch) {
    const float y = yaw * std::numbers::pi_v<float> / 180, p = pitch * std::numbers::pi_v<float> / 180;
    return Vec3f(std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y));
  };
  EXPECT_EQ(anglesAboutUp(Vec3f::UnitY(), {65.0f, 20.0f}), std::make_pair(65.0f, 20.0f));
  for (const Vec3f& up : {Vec3f(0, 0, 1), Vec3f(0, -1, 0), Vec3f(-1, 0, 0)})
    for (auto [yaw, pitch] : {std::pair{65.0f, 20.0f}, {25.0f, 65.0f}, {-120.0f, -30.0f}}) {
      const auto [yawUp, pitchUp] = anglesAboutUp(up, {yaw, pitch});
      EXPECT_TRUE((upFrame(up) * eye(yawUp, pitchUp)).isApprox(eye(yaw, pitch), 1e-5f)) << up.transpose();
    }
}

// The camera orbits the model's up: a model turned to stand on -Z, shown with up = -Z, looks as
// the upright model does with +Y; with the default +Y it does not.
TEST(ViewUp, RenderOrbitsAroundUp) {
  RenderOptions options;
  options.width = options.height = 48;
  options.supersample = 1;
  const Mesh upright = pyramid();
  const Image reference = renderMesh(upright, options);
  const Vec3f up = -Vec3f::UnitZ();
  const Mesh turned = transformed(upright, quarterTurnTo(up));
  auto meanDifference = [&](const Image& image) {
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        sum += (test::pixelColor(image, x, y) - test::pixelColor(reference, x, y)).cwiseAbs().sum();
    return sum / (3.0 * image.width * image.height);
  };
  options.up = viewUpDirection(turned);
  ASSERT_EQ(options.up, up);
  EXPECT_LT(meanDifference(renderMesh(turned, options)), 0.01);
  options.up = Vec3f::UnitY();
  EXPECT_GT(meanDifference(renderMesh(turned, options)), 0.05);
  options.up = Vec3f::Zero();
  test::expectParameterError([&] { renderMesh(turned, options); }, "up");
}
