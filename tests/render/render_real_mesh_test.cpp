#include <gtest/gtest.h>

#include "render_test_helpers.h"
#include "test_support.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/render_mesh.h"
#include "texsynth/render/view_up.h"

using namespace texsynth;
using namespace texsynth::test;

// The fitted camera keeps a real scanned mesh whole and centred from every direction:
// the image border stays background and the silhouette is substantial.
TEST(RenderRealMesh, BunnyIsWhollyVisibleFromAnyAngle) {
  const auto path = cgalMesh("bunny00.off");
  TS_REQUIRE_DATA(path);
  const Mesh bunny = readMesh(*path);
  RenderOptions options;
  options.width = 96;
  options.height = 72;
  options.supersample = 1;
  for (auto [yaw, pitch] : {std::pair{0.0f, 0.0f}, {30.0f, 20.0f}, {135.0f, -60.0f}, {270.0f, 89.0f}}) {
    options.yawDegrees = yaw;
    options.pitchDegrees = pitch;
    const Image image = renderMesh(bunny, options);
    bool borderClear = true;
    for (int x = 0; x < image.width; ++x)
      borderClear = borderClear && isBackground(image, x, 0, options.background) &&
                    isBackground(image, x, image.height - 1, options.background);
    for (int y = 0; y < image.height; ++y)
      borderClear = borderClear && isBackground(image, 0, y, options.background) &&
                    isBackground(image, image.width - 1, y, options.background);
    EXPECT_TRUE(borderClear) << "yaw " << yaw << " pitch " << pitch;
    EXPECT_GT(foreground(image, options.background).count, image.width * image.height / 10) << "yaw " << yaw;
  }
}

// The view up of CGAL's meshes: each stands on the floor it was modelled on (viewUpDirection).
TEST(RenderRealMesh, ViewUpStandsCgalMeshesUpright) {
  const std::pair<const char*, Vec3f> expected[] = {
      {"dino.off", Vec3f::UnitZ()},     {"pig.off", -Vec3f::UnitY()},    {"cow.off", Vec3f::UnitY()},
      {"elephant.off", Vec3f::UnitY()}, {"bunny00.off", Vec3f::UnitY()}, {"armadillo.off", Vec3f::UnitY()},
      {"sphere.off", Vec3f::UnitY()},   {"cube.off", Vec3f::UnitY()},    {"fandisk.off", -Vec3f::UnitY()}};
  for (const auto& [name, up] : expected) {
    const auto path = cgalMesh(name);
    TS_REQUIRE_DATA(path);
    EXPECT_EQ(viewUpDirection(readMesh(*path)), up) << name;
  }
}
