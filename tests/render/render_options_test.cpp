#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "texsynth/core/error.h"
#include "texsynth/render/primitives.h"
#include "texsynth/render/render_mesh.h"

using namespace texsynth;

namespace {

// Expects `render` to throw ParameterError naming `parameter`.
void expectParameterError(const std::string& parameter, const std::function<void()>& render) {
  try {
    render();
    ADD_FAILURE() << "no error for " << parameter;
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), parameter) << e.what();
  }
}

}  // namespace

TEST(RenderOptions, InvalidOptionsThrowNamingTheOption) {
  const Mesh box = makeBoxMesh(Vec3f::Zero(), Vec3f::Ones());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto with = [&](const std::function<void(RenderOptions&)>& change) {
    RenderOptions options;
    options.width = options.height = 8;
    change(options);
    return [=] { renderMesh(box, options); };
  };
  expectParameterError("width", with([](RenderOptions& o) { o.width = 0; }));
  expectParameterError("width", with([](RenderOptions& o) { o.width = 20000; }));
  expectParameterError("height", with([](RenderOptions& o) { o.height = -3; }));
  expectParameterError("supersample", with([](RenderOptions& o) { o.supersample = 0; }));
  expectParameterError("supersample", with([](RenderOptions& o) { o.supersample = 17; }));
  expectParameterError("supersample", with([](RenderOptions& o) { o.width = 8192, o.supersample = 3; }));
  expectParameterError("fovDegrees", with([](RenderOptions& o) { o.fovDegrees = 0; }));
  expectParameterError("fovDegrees", with([](RenderOptions& o) { o.fovDegrees = 180; }));
  expectParameterError("yawDegrees", with([=](RenderOptions& o) { o.yawDegrees = nan; }));
  expectParameterError("pitchDegrees",
                       with([](RenderOptions& o) { o.pitchDegrees = std::numeric_limits<float>::infinity(); }));
  expectParameterError("margin", with([](RenderOptions& o) { o.margin = -0.1f; }));
  expectParameterError("ambient", with([](RenderOptions& o) { o.ambient = 1.5f; }));
  expectParameterError("ambient", with([=](RenderOptions& o) { o.ambient = nan; }));
  expectParameterError("lightDirection", with([](RenderOptions& o) { o.lightDirection = Vec3f::Zero(); }));
  expectParameterError("background", with([=](RenderOptions& o) { o.background = Vec3f(nan, 0, 0); }));
  expectParameterError("defaultColor", with([=](RenderOptions& o) { o.defaultColor = Vec3f(0, nan, 0); }));

  RenderOptions small;
  small.width = small.height = 8;
  SurfaceColorFunction tooFew = [](const std::vector<Vec3f>&, const std::vector<Vec3f>&, std::vector<Vec3f>& colors) {
    colors.assign(1, Vec3f::Zero());
  };
  expectParameterError("colorAt", [&] { renderMesh(box, tooFew, small); });
  expectParameterError("colorAt", [&] { renderMesh(box, SurfaceColorFunction(), small); });
  expectParameterError("yawPitch", [&] { renderViews(box, nullptr, {}, small); });
  expectParameterError("width", [&] {
    RenderOptions bad = small;
    bad.width = 0;
    renderViews(box, nullptr, {{0.0f, 0.0f}}, bad);
  });
}

TEST(RenderOptions, DefaultsAreValid) {
  EXPECT_NO_THROW(validateRenderOptions(RenderOptions()));
}

TEST(RenderOptions, InvalidMeshesThrowInputError) {
  RenderOptions options;
  options.width = options.height = 8;
  Mesh empty;
  EXPECT_THROW(renderMesh(empty, options), InputError);
  Mesh badIndex;
  badIndex.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  badIndex.triangles = {{0, 1, 3}};
  EXPECT_THROW(renderMesh(badIndex, options), InputError);
  Mesh notFinite = badIndex;
  notFinite.triangles = {{0, 1, 2}};
  notFinite.positions[1].x() = std::numeric_limits<float>::infinity();
  EXPECT_THROW(renderMesh(notFinite, options), InputError);
  Mesh wrongColors = notFinite;
  wrongColors.positions[1].x() = 1;
  wrongColors.colors = {Vec3f::Ones()};
  EXPECT_THROW(renderMesh(wrongColors, options), InputError);
}
