#include "texsynth/render/render_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render_test_helpers.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using namespace texsynth::test;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

RenderOptions frontView(int size) {
  RenderOptions options;
  options.width = options.height = size;
  options.yawDegrees = 0;
  options.pitchDegrees = 0;
  return options;
}

// Shade of a surface facing the camera straight on, per the documented Lambert model.
float frontShade(const RenderOptions& options) {
  return options.ambient + (1 - options.ambient) * std::abs(options.lightDirection.normalized().z());
}

// A quad in the plane n.p = offset, spanned by two unit vectors orthogonal to n.
Mesh tiltedQuad(const Vec3f& normal, float offset) {
  Vec3f n = normal.normalized();
  Vec3f u = n.unitOrthogonal(), v = n.cross(u);
  Mesh quad;
  for (const Vec3f& corner : std::initializer_list<Vec3f>{-u - v, u - v, u + v, -u + v})
    quad.positions.push_back(offset * n + corner);
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  return quad;
}

}  // namespace

TEST(RenderMesh, CubeFromFrontCoversItsProjectedArea) {
  RenderOptions options = frontView(200);
  options.supersample = 4;
  const Image image = renderMesh(makeBoxMesh(Vec3f::Constant(-1), Vec3f::Constant(1)), options);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  ASSERT_EQ(image.channels, 3);

  // Only the front face (z = 1) is visible; its projected side follows from the documented fit.
  const float halfFov = 0.5f * options.fovDegrees * kPi / 180;
  const float distance = std::sqrt(3.0f) * (1 + options.margin) / std::sin(halfFov);
  const float focal = 100 / std::tan(halfFov);
  const float side = 2 * focal / (distance - 1);
  const float shaded = options.defaultColor.x() * frontShade(options);

  EXPECT_NEAR(image.at(100, 100, 0), shaded, 1e-5f);
  EXPECT_NEAR(image.at(100, 100, 2), shaded, 1e-5f);
  double coverage = 0;  // each pixel mixes `shaded` and white background by its coverage
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) coverage += (1.0 - image.at(x, y, 0)) / (1.0 - shaded);
  EXPECT_NEAR(coverage, side * side, 0.01 * side * side);
  EXPECT_TRUE(isBackground(image, 0, 0, options.background));
}

TEST(RenderMesh, NearTriangleHidesFarOneInAnyOrder) {
  const Vec3f red(1, 0, 0), blue(0, 0, 1);
  auto triangleAt = [](Mesh& mesh, float z, const Vec3f& color) {
    addColoredTriangle(mesh, {-1, -1, z}, {1, -1, z}, {0, 1, z}, color);
  };
  Mesh nearFirst, farFirst;
  triangleAt(nearFirst, 0.5f, red);
  triangleAt(nearFirst, -0.5f, blue);
  triangleAt(farFirst, -0.5f, blue);
  triangleAt(farFirst, 0.5f, red);
  for (const Mesh& mesh : {nearFirst, farFirst}) {
    const Image image = renderMesh(mesh, frontView(64));
    const Vec3f centre = pixelColor(image, 32, 32);
    EXPECT_GT(centre.x(), 0.5f);
    EXPECT_EQ(centre.z(), 0.0f);
  }
}

TEST(RenderMesh, EqualDepthGoesToTheSmallerTriangleIndex) {
  const Vec3f red(1, 0, 0), blue(0, 0, 1);
  for (bool redFirst : {true, false}) {
    Mesh mesh;
    addColoredTriangle(mesh, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, redFirst ? red : blue);
    addColoredTriangle(mesh, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, redFirst ? blue : red);
    const Image image = renderMesh(mesh, frontView(48));
    const ForegroundStats stats = foreground(image, Vec3f::Ones());
    ASSERT_GT(stats.count, 100);
    // Edge pixels mix with the white background, so compare channels on the pure interior.
    const Vec3f centre = pixelColor(image, 24, 24);
    EXPECT_EQ(redFirst ? centre.z() : centre.x(), 0.0f);
    EXPECT_GT(redFirst ? centre.x() : centre.z(), 0.5f);
  }
}

TEST(RenderMesh, PerVertexColorsAppear) {
  Mesh sphere = makeUvSphereMesh(Vec3f::Zero(), 1, 16, 32);
  sphere.colors.assign(sphere.vertexCount(), Vec3f(0.9f, 0.1f, 0.1f));
  const ForegroundStats stats = foreground(renderMesh(sphere, frontView(64)), Vec3f::Ones());
  ASSERT_GT(stats.count, 500);
  EXPECT_GT(stats.mean.x(), 2 * stats.mean.y());
  EXPECT_GT(stats.mean.x(), 2 * stats.mean.z());

  sphere.colors.clear();  // no colours: light gray
  const ForegroundStats gray = foreground(renderMesh(sphere, frontView(64)), Vec3f::Ones());
  EXPECT_NEAR(gray.mean.x(), gray.mean.z(), 1e-5f);
}

TEST(RenderMesh, ColorFunctionGetsPointsOnTheSurfaceInOneBatch) {
  const Vec3f normal = Vec3f(1, 2, 3).normalized();
  const float offset = 0.7f;
  int calls = 0;
  std::size_t pointCount = 0;
  float worstPlaneDistance = 0, worstNormalError = 0;
  SurfaceColorFunction green = [&](const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals,
                                   std::vector<Vec3f>& colors) {
    ++calls;
    pointCount = points.size();
    ASSERT_EQ(normals.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      worstPlaneDistance = std::max(worstPlaneDistance, std::abs(points[i].dot(normal) - offset));
      worstNormalError = std::max(worstNormalError, 1 - std::abs(normals[i].dot(normal)));
    }
    colors.assign(points.size(), Vec3f(0, 1, 0));
  };
  RenderOptions options;
  options.width = 96;
  options.height = 64;
  const Image image = renderMesh(tiltedQuad(normal, offset), green, options);
  EXPECT_EQ(calls, 1);
  EXPECT_GT(pointCount, 1000u);
  EXPECT_LT(worstPlaneDistance, 1e-5f);
  EXPECT_LT(worstNormalError, 1e-5f);
  const ForegroundStats stats = foreground(image, options.background);
  EXPECT_GT(stats.mean.y(), 2 * stats.mean.x());
}

// Every point handed to the colour function must lie on the ray through its sample's centre:
// projected with the documented camera it lands on a sample centre, in raster order. Affine
// (not perspective-correct) interpolation would put points whole samples away.
TEST(RenderMesh, ColorFunctionPointsArePerspectiveCorrect) {
  Mesh floor;
  floor.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  floor.triangles = {{0, 1, 2}, {0, 2, 3}};
  RenderOptions options;
  options.width = 80;
  options.height = 60;
  options.fovDegrees = 90;
  options.yawDegrees = 25;
  options.pitchDegrees = 35;
  options.supersample = 2;
  std::vector<Vec3f> seen;
  SurfaceColorFunction record = [&](const std::vector<Vec3f>& points, const std::vector<Vec3f>&,
                                    std::vector<Vec3f>& colors) {
    seen = points;
    colors.assign(points.size(), Vec3f::Ones());
  };
  renderMesh(floor, record, options);
  ASSERT_GT(seen.size(), 1000u);

  const float halfFov = 0.5f * options.fovDegrees * kPi / 180;
  const float distance = std::sqrt(2.0f) * (1 + options.margin) / std::sin(halfFov);
  const Mat3f cameraToWorld = (Eigen::AngleAxisf(options.yawDegrees * kPi / 180, Vec3f::UnitY()) *
                               Eigen::AngleAxisf(-options.pitchDegrees * kPi / 180, Vec3f::UnitX()))
                                  .toRotationMatrix();
  const Vec3f eye = cameraToWorld * Vec3f(0, 0, distance);
  const float focal = 60.0f / std::tan(halfFov);  // smaller side: 60 pixels * 2 samples / 2
  float worstOffset = 0;
  long previousIndex = -1;
  bool rasterOrder = true;
  for (const Vec3f& p : seen) {
    Vec3f v = cameraToWorld.transpose() * (p - eye);
    float sx = 80 + focal * v.x() / -v.z(), sy = 60 - focal * v.y() / -v.z();
    worstOffset = std::max({worstOffset, std::abs(sx - std::floor(sx) - 0.5f), std::abs(sy - std::floor(sy) - 0.5f)});
    long index = long(std::floor(sy)) * 160 + long(std::floor(sx));
    rasterOrder = rasterOrder && index > previousIndex;
    previousIndex = index;
  }
  EXPECT_LT(worstOffset, 0.02f);
  EXPECT_TRUE(rasterOrder);
}

TEST(RenderMesh, ImageIsOrientedNotMirroredOrUpsideDown) {
  // Red box on +X, green on +Y, blue on +Z, gray centre.
  Mesh scene;
  appendMesh(scene, makeBoxMesh(Vec3f::Constant(-0.3f), Vec3f::Constant(0.3f)), Vec3f(0.5f, 0.5f, 0.5f));
  appendMesh(scene, makeBoxMesh(Vec3f(0.7f, -0.2f, -0.2f), Vec3f(1.1f, 0.2f, 0.2f)), Vec3f(1, 0, 0));
  appendMesh(scene, makeBoxMesh(Vec3f(-0.2f, 0.7f, -0.2f), Vec3f(0.2f, 1.1f, 0.2f)), Vec3f(0, 1, 0));
  appendMesh(scene, makeBoxMesh(Vec3f(-0.2f, -0.2f, 0.7f), Vec3f(0.2f, 0.2f, 1.1f)), Vec3f(0, 0, 1));
  // Centroid (in pixels) of the pixels dominated by one channel.
  auto centroidOf = [](const Image& image, int channel) {
    Vec2f sum = Vec2f::Zero();
    int count = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        Vec3f c = pixelColor(image, x, y);
        if (c[channel] > 0.2f && c[channel] > 3 * (c.sum() - c[channel])) sum += Vec2f(float(x), float(y)), ++count;
      }
    EXPECT_GT(count, 0) << "channel " << channel;
    return Vec2f(sum / float(std::max(count, 1)));
  };
  const Image front = renderMesh(scene, frontView(96));  // camera on +Z: x right, y up
  EXPECT_GT(centroidOf(front, 0).x(), 60);               // +X to the right
  EXPECT_LT(centroidOf(front, 1).y(), 36);               // +Y at the top
  RenderOptions side = frontView(96);
  side.yawDegrees = 90;  // camera on +X looking towards -X: +Z is on the left
  const Image fromRight = renderMesh(scene, side);
  EXPECT_LT(centroidOf(fromRight, 2).x(), 36);
  EXPECT_LT(centroidOf(fromRight, 1).y(), 36);
  RenderOptions above = frontView(96);
  above.pitchDegrees = 90;  // looking straight down, image up is -Z: +Z at the bottom
  EXPECT_GT(centroidOf(renderMesh(scene, above), 2).y(), 60);
}

TEST(RenderMesh, BitwiseIdenticalForAnyThreadCount) {
  const Mesh sphere = makeUvSphereMesh(Vec3f(0.1f, 0.2f, 0.3f), 1.3f, 40, 80);
  SurfaceColorFunction checker = [](const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals,
                                    std::vector<Vec3f>& colors) {
    colors.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      Vec3i cell = (points[i] * 4).array().floor().cast<int>();
      colors[i] = (cell.sum() & 1) ? Vec3f(0.9f, 0.6f, 0.2f) : 0.5f * (normals[i] + Vec3f::Ones());
    }
  };
  RenderOptions options;
  options.width = 160;
  options.height = 120;
  options.supersample = 3;
  Image single, dual, again;
  {
    ThreadLimit limit(1);
    single = renderMesh(sphere, checker, options);
  }
  {
    ThreadLimit limit(2);
    dual = renderMesh(sphere, checker, options);
    again = renderMesh(sphere, checker, options);
  }
  EXPECT_TRUE(single.pixels == dual.pixels);
  EXPECT_TRUE(dual.pixels == again.pixels);
  EXPECT_GT(foreground(single, options.background).count, 5000);
}

TEST(RenderMesh, DegenerateTrianglesDrawNothing) {
  Mesh good;
  good.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {0, -1, 0}};
  good.triangles = {{0, 1, 2}};
  Mesh withDegenerate = good;
  // Zero area: a repeated vertex, and three collinear vertices along the bottom edge.
  withDegenerate.triangles = {{0, 0, 2}, {0, 3, 1}, {0, 1, 2}, {2, 2, 2}};
  const RenderOptions options = frontView(64);
  EXPECT_TRUE(renderMesh(good, options).pixels == renderMesh(withDegenerate, options).pixels);

  Mesh allDegenerate = good;
  allDegenerate.triangles = {{0, 3, 1}, {1, 1, 1}};
  EXPECT_EQ(foreground(renderMesh(allDegenerate, options), options.background).count, 0);
  Mesh collapsed;  // every vertex at one point
  collapsed.positions = {{2, 2, 2}, {2, 2, 2}, {2, 2, 2}};
  collapsed.triangles = {{0, 1, 2}};
  EXPECT_EQ(foreground(renderMesh(collapsed, options), options.background).count, 0);
}

TEST(RenderMesh, OpenMeshIsLitFromBothSides) {
  // One triangle facing away from the camera must still be lit like one facing it.
  Mesh facing, away;
  facing.positions = away.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  facing.triangles = {{0, 1, 2}};
  away.triangles = {{0, 2, 1}};
  RenderOptions options = frontView(32);
  options.smoothShading = false;
  const Image a = renderMesh(facing, options), b = renderMesh(away, options);
  EXPECT_NEAR(a.at(16, 16, 0), options.defaultColor.x() * frontShade(options), 1e-5f);
  EXPECT_TRUE(a.pixels == b.pixels);
}

TEST(RenderViews, PlacesViewsSideBySide) {
  const Mesh box = makeBoxMesh(Vec3f(-1, -0.5f, -0.2f), Vec3f(1, 0.5f, 0.2f));
  RenderOptions options;
  options.width = 40;
  options.height = 30;
  const std::vector<std::pair<float, float>> views{{0, 0}, {90, 10}, {200, -30}};
  const Image montage = renderViews(box, nullptr, views, options);
  ASSERT_EQ(montage.width, 120);
  ASSERT_EQ(montage.height, 30);
  for (std::size_t v = 0; v < views.size(); ++v) {
    RenderOptions one = options;
    one.yawDegrees = views[v].first;
    one.pitchDegrees = views[v].second;
    const Image single = renderMesh(box, one);
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 40; ++x)
        ASSERT_EQ(pixelColor(single, x, y), pixelColor(montage, int(v) * 40 + x, y)) << "view " << v;
  }
  int calls = 0;
  SurfaceColorFunction count = [&](const std::vector<Vec3f>& p, const std::vector<Vec3f>&, std::vector<Vec3f>& c) {
    ++calls;
    c.assign(p.size(), Vec3f::Zero());
  };
  renderViews(box, &count, views, options);
  EXPECT_EQ(calls, 3);
}

TEST(RenderMesh, ClosedMeshHasNoCracks) {
  // A sphere's silhouette is convex: in every row, the pixels between the first and last
  // covered ones must all be covered; a crack along a shared edge would show background.
  RenderOptions options = frontView(128);
  options.supersample = 1;
  options.yawDegrees = 17;
  options.pitchDegrees = -23;
  const Image image = renderMesh(makeUvSphereMesh(Vec3f::Zero(), 1, 64, 128), options);
  int coveredRows = 0;
  for (int y = 0; y < image.height; ++y) {
    int first = -1, last = -1;
    for (int x = 0; x < image.width; ++x)
      if (!isBackground(image, x, y, options.background)) last = x, first = first < 0 ? x : first;
    if (first < 0) continue;
    ++coveredRows;
    for (int x = first; x <= last; ++x) ASSERT_FALSE(isBackground(image, x, y, options.background)) << x << ", " << y;
  }
  EXPECT_GT(coveredRows, 64);
}

TEST(RenderMesh, SharedEdgeThroughSampleCentresLeavesNoGap) {
  // Seen straight on, the quad's diagonal passes exactly through the sample centres
  // (k + 0.5, k + 0.5) around the image centre: both triangles must claim them.
  Mesh quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.triangles = {{0, 1, 3}, {1, 2, 3}};  // the shared edge runs from (1, -1) to (-1, 1)
  RenderOptions options = frontView(64);
  options.supersample = 1;
  const Image image = renderMesh(quad, options);
  for (int k = 20; k < 44; ++k) EXPECT_FALSE(isBackground(image, k, 63 - k, options.background)) << k;
  for (int k = 20; k < 44; ++k) EXPECT_FALSE(isBackground(image, k, k, options.background)) << k;
}
