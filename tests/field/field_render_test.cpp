// Field glyph renders: the views are there and show the three axis colours and the curves.
#include "texsynth/field/field_render.h"

#include <gtest/gtest.h>

#include "field_test_support.h"
#include "texsynth/geometry/mesh_cut.h"
#include "texsynth/render/glyph_mesh.h"

using namespace texsynth;

namespace {

// Pixels close to a colour (shading darkens, so compare hue-like ratios loosely).
int countDominant(const Image& image, int channel) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.pixel(x, y);
      float other = std::max(p[(channel + 1) % 3], p[(channel + 2) % 3]);
      count += p[channel] > 0.15f && p[channel] > 2.0f * other;
    }
  return count;
}

}  // namespace

TEST(FieldRender, ShowsSurfaceAndCutWithAxisColoursAndCurves) {
  Mesh sphere = makeUvSphereMesh(Vec3f::Zero(), 1.0f, 24, 48);
  FieldDesignOptions options = test::smallGrid(10);
  options.grid.margin = 0.05f;
  FieldDesigner d(sphere, options);
  d.addCurve(test::surfaceCurve({{-0.6f, 0.0f, 0.8f}, {0.0f, 0.0f, 1.0f}, {0.6f, 0.0f, 0.8f}}));
  std::vector<std::vector<Vec3f>> curves;
  for (const auto& samples : d.curveSamples()) {
    curves.emplace_back();
    for (const CurveSample& s : samples) curves.back().push_back(s.position);
  }
  FieldRenderOptions render;
  render.render.width = render.render.height = 160;
  render.views = {{0, 0}};
  Image image = renderFieldGlyphs(sphere, d.field(), curves, render);
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 160);
  for (int c = 0; c < 3; ++c) EXPECT_GT(countDominant(image, c), 20) << "axis colour " << c;
  // Yellow curve: red and green high, blue low.
  int yellow = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < 160; ++x) {
      const float* p = image.pixel(x, y);
      yellow += p[0] > 0.5f && p[1] > 0.4f && p[2] < 0.2f;
    }
  EXPECT_GT(yellow, 10);
  render.glyphsAcross = 1;
  test::expectParameterError([&] { renderFieldGlyphs(sphere, d.field(), curves, render); }, "glyphsAcross");
}

TEST(GlyphMesh, SticksAndClippingBuildValidColouredGeometry) {
  Mesh m = coloredCopy(test::unitCube(), {0.5f, 0.5f, 0.5f});
  const std::size_t before = m.triangles.size();
  appendAxisGlyph(m, {0.5f, 0.5f, 0.5f}, Frame{}, 0.3f, 0.02f);
  EXPECT_EQ(m.triangles.size(), before + 3 * 12);
  EXPECT_EQ(m.colors.size(), m.positions.size());
  EXPECT_EQ(m.normals.size(), m.positions.size());
  m.validate("glyphs");
  appendStick(m, {0, 0, 0}, {0, 0, 0}, 0.1f, {1, 0, 0});  // zero length: nothing
  EXPECT_EQ(m.triangles.size(), before + 36);
  Mesh half = clipMesh(m, Vec3f::UnitX(), 0.5f);
  for (const Vec3i& t : half.triangles)
    EXPECT_LE((half.positions[t[0]] + half.positions[t[1]] + half.positions[t[2]]).x() / 3, 0.5f + 1e-6f);
  Mesh plain = test::unitCube();
  plain.colors.clear();
  test::expectParameterError([&] { appendStick(plain, {0, 0, 0}, {1, 0, 0}, 0.1f, {1, 0, 0}); }, "mesh");
}
