// Surface quality: a coherent copy of the exemplar on a flat retiled plane scores near 0, random
// exemplar pixels score high, a turned copy is coherent only rotation-invariantly, flatness and
// completeness tell a copy from a one-color surface (completeness also from part of a copy),
// borders are left out, thread count does not matter, bad input is rejected.
#include "texsynth/surface/surface_quality.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/geometry/mesh_retiling.h"

using namespace texsynth;

namespace {

// A smooth RGB texture with detail at a few pixels' scale (bilinear lookups reproduce it well).
Image smoothTexture(int size) {
  Image image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float fx = float(x), fy = float(y);
      image.at(x, y, 0) = 0.5f + 0.3f * std::sin(0.3f * fx + 1.5f * std::sin(0.11f * fy));
      image.at(x, y, 1) = 0.5f + 0.25f * std::sin(0.21f * fy + 1.2f * std::cos(0.09f * fx));
      image.at(x, y, 2) = 0.5f + 0.2f * std::sin(0.17f * (fx + fy)) * std::cos(0.13f * (fx - fy));
    }
  return image;
}

// The square [0, side]^2 in z = 0, retiled to about `vertices` near-uniform vertices.
Mesh retiledPlane(float side, int vertices) {
  Mesh grid;
  const int n = 8;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) grid.positions.push_back({side * float(x) / n, side * float(y) / n, 0});
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int v = y * (n + 1) + x;
      grid.triangles.push_back({v, v + 1, v + n + 2});
      grid.triangles.push_back({v, v + n + 2, v + n + 1});
    }
  RetileOptions options;
  options.targetVertices = vertices;
  return retileMesh(grid, options, "plane");
}

double spacingOf(const Mesh& mesh) {
  return std::sqrt(mesh.surfaceArea() / double(mesh.vertexCount()));
}

// Colors every vertex by a bilinear lookup of `exemplar` at its planar position, one pixel per
// spacing, exemplar x along +x and exemplar y (down) along -y (the layout of tangent +x), from
// pixel (x0, y0) at the origin; `turned` swaps the exemplar's axes (a quarter turn and a mirror).
void colorCoherently(Mesh& mesh, const Image& exemplar, double x0, double y0, bool turned = false) {
  const double s = spacingOf(mesh);
  mesh.colors.clear();
  for (const Vec3f& p : mesh.positions) {
    double u = x0 + p.x() / s, v = y0 - p.y() / s;
    if (turned) std::swap(u, v);
    float rgb[3];
    exemplar.sampleBilinearWrapped(u, v, rgb);
    mesh.colors.push_back({rgb[0], rgb[1], rgb[2]});
  }
}

// Colors every vertex by the exemplar pixel under it (as colorCoherently, without interpolation):
// what surface synthesis does, one exemplar pixel per vertex.
void colorByPixel(Mesh& mesh, const Image& exemplar, double x0, double y0) {
  const double s = spacingOf(mesh);
  mesh.colors.clear();
  for (const Vec3f& p : mesh.positions) {
    const int x = int(std::floor(x0 + p.x() / s)) % exemplar.width,
              y = int(std::floor(y0 - p.y() / s)) % exemplar.height;
    mesh.colors.push_back({exemplar.at(x, y, 0), exemplar.at(x, y, 1), exemplar.at(x, y, 2)});
  }
}

// A fine texture: smoothTexture with per-pixel noise of about its own amplitude.
Image fineTexture(int size) {
  Image image = smoothTexture(size);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] += 0.3f * (uniform01(hashKey(5, i)) - 0.5f);
  return image;
}

void colorRandomly(Mesh& mesh, const Image& exemplar) {
  mesh.colors.clear();
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    const int x = int(uniformBelow(hashKey(9, v, 0), std::uint32_t(exemplar.width)));
    const int y = int(uniformBelow(hashKey(9, v, 1), std::uint32_t(exemplar.height)));
    mesh.colors.push_back({exemplar.at(x, y, 0), exemplar.at(x, y, 1), exemplar.at(x, y, 2)});
  }
}

void colorUniformly(Mesh& mesh, Vec3f color) {
  mesh.colors.assign(mesh.vertexCount(), color);
}

std::vector<Vec3f> alongX(const Mesh& mesh) {
  return std::vector<Vec3f>(mesh.vertexCount(), Vec3f::UnitX());
}

class SurfaceQualityTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    plane_ = new Mesh(retiledPlane(40.0f, 1600));
    exemplar_ = new Image(smoothTexture(64));
  }
  static void TearDownTestSuite() {
    delete plane_;
    delete exemplar_;
  }
  static Mesh* plane_;
  static Image* exemplar_;
};
Mesh* SurfaceQualityTest::plane_ = nullptr;
Image* SurfaceQualityTest::exemplar_ = nullptr;

TEST_F(SurfaceQualityTest, CoherentCopyScoresNearZeroRandomPixelsHigh) {
  Mesh coherent = *plane_, random = *plane_;
  colorCoherently(coherent, *exemplar_, 12, 52);
  colorRandomly(random, *exemplar_);
  const SurfaceQuality good = evaluateSurface(*exemplar_, coherent, alongX(coherent));
  SurfaceQualityOptions sample;  // random colors defeat the exact search's pruning: 400 vertices are plenty
  sample.samples = 400;
  const SurfaceQuality bad = evaluateSurface(*exemplar_, random, alongX(random), sample);
  // Not 0: vertices sit at sub-pixel offsets from the exemplar's pixel grid (3.3 here).
  EXPECT_LT(good.coherence, 5.0);
  EXPECT_GT(bad.coherence, 8 * good.coherence);  // 39
  EXPECT_LE(good.rotationInvariant, good.coherence);
  EXPECT_LE(bad.rotationInvariant, bad.coherence);
  EXPECT_GT(bad.rotationInvariant, 5 * good.coherence);
  // The plane has a border: its outer strip is left out, the rest sampled.
  EXPECT_GT(good.nearBorder, 0);
  EXPECT_EQ(good.evaluated + good.nearBorder, int(coherent.vertexCount()));
  EXPECT_NEAR(good.spacing, spacingOf(coherent), 1e-9);
  EXPECT_LT(good.histogram, 8.0);  // a window of the exemplar: a similar distribution
}

TEST_F(SurfaceQualityTest, TurnedCopyIsCoherentOnlyRotationInvariantly) {
  Mesh turned = *plane_, straight = *plane_;
  colorCoherently(turned, *exemplar_, 12, 52, true);
  colorCoherently(straight, *exemplar_, 12, 52);
  const SurfaceQuality q = evaluateSurface(*exemplar_, turned, alongX(turned));
  const SurfaceQuality reference = evaluateSurface(*exemplar_, straight, alongX(straight));
  EXPECT_GT(q.coherence, 4 * q.rotationInvariant);
  EXPECT_LT(q.rotationInvariant, 1.5 * reference.coherence + 0.5);
  // Tangents along the texture's turned x axis (+y: exemplar y runs along -x there, a mirror) do
  // not help the plain measure of a transposed copy; the invariant one stays the same.
  const std::vector<Vec3f> alongY(turned.vertexCount(), Vec3f::UnitY());
  const SurfaceQuality turnedTangents = evaluateSurface(*exemplar_, turned, alongY);
  EXPECT_GT(turnedTangents.coherence, 4 * turnedTangents.rotationInvariant);
  EXPECT_NEAR(turnedTangents.rotationInvariant, q.rotationInvariant, 0.5);
}

TEST_F(SurfaceQualityTest, FlatnessIsNearZeroForACopyAndHighForOneColor) {
  Mesh coherent = *plane_, pixels = *plane_, uniform = *plane_;
  colorCoherently(coherent, *exemplar_, 12, 52);
  const Image fine = fineTexture(64);
  colorByPixel(pixels, fine, 12, 52);
  colorUniformly(uniform, {0.5f, 0.4f, 0.3f});
  const SurfaceQuality copy = evaluateSurface(*exemplar_, coherent, alongX(coherent));
  // Resampling between vertices blurs a fine texture: the exemplar's patches are resampled too
  // before they set the threshold, or this would read 0.3.
  const SurfaceQuality fineCopy = evaluateSurface(fine, pixels, alongX(pixels));
  const SurfaceQuality flat = evaluateSurface(*exemplar_, uniform, alongX(uniform));
  EXPECT_LT(std::abs(copy.flatness), 0.05);      // 0.022
  EXPECT_LT(std::abs(fineCopy.flatness), 0.08);  // -0.043
  EXPECT_DOUBLE_EQ(flat.flatness, 0.9);          // every patch flat
  // (Random colors read -0.1, no patch as flat as the exemplar's flattest tenth: left out, as
  // their exact searches take a third of this test's time under the sanitizers.)
}

TEST_F(SurfaceQualityTest, CompletenessIsLowForAFullCopyHigherForPartOfItHighForOneColor) {
  // The copy's evaluated middle shows texture pixels 18..46 along both axes: all of a 24-pixel
  // window at 20, about half of a window twice as wide (and nothing outside either).
  const Image window = exemplar_->crop(20, 20, 24, 24), wide = exemplar_->crop(20, 20, 44, 24);
  Mesh coherent = *plane_, uniform = *plane_;
  colorCoherently(coherent, *exemplar_, 12, 52);
  colorUniformly(uniform, {0.5f, 0.5f, 0.5f});
  const SurfaceQuality full = evaluateSurface(window, coherent, alongX(coherent));
  const SurfaceQuality half = evaluateSurface(wide, coherent, alongX(coherent));
  const SurfaceQuality none = evaluateSurface(window, uniform, alongX(uniform));
  EXPECT_LT(full.completeness, 5.0);                    // 3.5: vertices fall between the exemplar's pixels
  EXPECT_GT(half.completeness, 2 * full.completeness);  // 8.1
  EXPECT_GT(none.completeness, 4 * half.completeness);  // 43.5
}

TEST_F(SurfaceQualityTest, BordersAreLeftOutUnlessAsked) {
  Mesh coherent = *plane_;
  colorCoherently(coherent, *exemplar_, 12, 52);
  SurfaceQualityOptions options;
  options.samples = 0;
  const SurfaceQuality inside = evaluateSurface(*exemplar_, coherent, alongX(coherent), options);
  options.skipBorders = false;
  const SurfaceQuality everywhere = evaluateSurface(*exemplar_, coherent, alongX(coherent), options);
  EXPECT_EQ(everywhere.evaluated, int(coherent.vertexCount()));
  EXPECT_EQ(everywhere.nearBorder, 0);
  EXPECT_GT(everywhere.coherence, inside.coherence);  // clamp-to-edge patches are no texture
}

TEST_F(SurfaceQualityTest, SameResultForAnyThreadCountAndSeededSample) {
  // A coherent copy, not random colors: its exact searches are quick (random patches make the
  // KD-tree visit most of its leaves, seconds under the sanitizers).
  Mesh random = *plane_;
  colorCoherently(random, *exemplar_, 12, 52);
  SurfaceQualityOptions options;
  options.samples = 500;
  SurfaceQuality one, two;
  {
    ThreadLimit limit(1);
    one = evaluateSurface(*exemplar_, random, alongX(random), options);
  }
  {
    ThreadLimit limit(2);
    two = evaluateSurface(*exemplar_, random, alongX(random), options);
  }
  EXPECT_EQ(one.evaluated, 500);
  EXPECT_EQ(one.coherence, two.coherence);
  EXPECT_EQ(one.rotationInvariant, two.rotationInvariant);
  EXPECT_EQ(one.histogram, two.histogram);
  EXPECT_EQ(one.completeness, two.completeness);
  EXPECT_EQ(one.flatness, two.flatness);
  options.seed = 2;  // another sample: close, but not the same vertices
  const SurfaceQuality other = evaluateSurface(*exemplar_, random, alongX(random), options);
  EXPECT_NE(other.coherence, one.coherence);
  EXPECT_NEAR(other.coherence, one.coherence, 0.1 * one.coherence);
}

TEST_F(SurfaceQualityTest, RejectsBadInput) {
  Mesh mesh = *plane_;
  const std::vector<Vec3f> tangents = alongX(mesh);
  test::expectInputError([&] { evaluateSurface(*exemplar_, mesh, tangents); }, "mesh", "no vertex colors");
  colorRandomly(mesh, *exemplar_);
  SurfaceQualityOptions options;
  options.patchSize = 6;
  test::expectParameterError([&] { evaluateSurface(*exemplar_, mesh, tangents, options); }, "patchSize");
  options.patchSize = 1;
  test::expectParameterError([&] { evaluateSurface(*exemplar_, mesh, tangents, options); }, "patchSize");
  options = {};
  options.samples = -1;
  test::expectParameterError([&] { evaluateSurface(*exemplar_, mesh, tangents, options); }, "samples");
  test::expectParameterError([&] { evaluateSurface(*exemplar_, mesh, std::span(tangents).subspan(1)); }, "tangents");
  test::expectParameterError([&] { evaluateSurface(Image(5, 5, 3), mesh, tangents); }, "exemplar");
  test::expectParameterError([&] { evaluateSurface(Image(), mesh, tangents); }, "exemplar");
  Mesh nan = mesh;
  nan.colors[7].x() = std::nanf("");
  test::expectInputError([&] { evaluateSurface(*exemplar_, nan, tangents); }, "mesh", "non-finite");
  Mesh short_ = mesh;
  short_.colors.pop_back();
  test::expectInputError([&] { evaluateSurface(*exemplar_, short_, tangents); }, "mesh", "colors");
  // A strip narrower than a patch: no vertex is clear of the border.
  Mesh strip = retiledPlane(4.0f, 100);
  colorRandomly(strip, *exemplar_);
  test::expectInputError([&] { evaluateSurface(*exemplar_, strip, alongX(strip)); }, "mesh", "border");
}

}  // namespace
