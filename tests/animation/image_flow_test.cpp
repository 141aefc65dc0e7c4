#include "texsynth/animation/image_flow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "test_support.h"
#include "texsynth/animation/flow_limits.h"
#include "texsynth/core/error.h"
#include "texsynth/core/math.h"
#include "texsynth/core/parallel.h"
#include "texsynth/io/image_io.h"

using namespace texsynth;
using test::expectInputError;
using test::TempDir;

namespace {

Vec2f velocityAt(const Image& v, int x, int y) {
  return {v.at(x, y, 0), v.at(x, y, 1)};
}

// 64 x 64 with the centre on pixel (32, 32)'s centre and a radius of 16 pixels.
Image centred(const std::string& preset, float strength = 2.0f) {
  const std::string spec = preset + ":strength=" + std::to_string(strength) + ",cx=0.5078125,cy=0.5078125,radius=0.25";
  return ImageFlow::parse(spec, 64, 64).velocities(0);
}

// A ParameterError("flow", ...) whose message holds `fragment`.
void expectFlowError(const std::function<void()>& run, const std::string& fragment) {
  try {
    run();
    ADD_FAILURE() << "accepted a bad flow; expected: " << fragment;
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), "flow");
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

// A 2-channel velocity image with values no 8-bit level can hold.
Image exrVelocities(int width, int height, float offset) {
  Image image(width, height, 2);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = offset + 0.013f * float(i % 97) - 0.6f;
  return image;
}

}  // namespace

TEST(ImageFlow, UniformIsExactEverywhereAndScaled) {
  const ImageFlow flow = ImageFlow::parse("uniform:dx=1.5,dy=-2", 7, 5, {.scale = 2.0f});
  const Image v = flow.velocities(3);
  ASSERT_EQ(v.width, 7);
  ASSERT_EQ(v.height, 5);
  ASSERT_EQ(v.channels, 2);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) EXPECT_EQ(velocityAt(v, x, y), Vec2f(3.0f, -4.0f));
  EXPECT_FALSE(flow.timeVarying());
  EXPECT_EQ(flow.width(), 7);
  EXPECT_EQ(flow.height(), 5);
  EXPECT_EQ(ImageFlow::parse("uniform", 4, 4).velocities(0).at(2, 2, 0), 1.0f);  // dx = 1, dy = 0 by default
}

TEST(ImageFlow, VortexIsTangentialAndClockwise) {
  const Image v = centred("vortex");
  // y points down: right of the centre moves down, above it moves right.
  EXPECT_NEAR(velocityAt(v, 48, 32).x(), 0.0f, 1e-5f);
  EXPECT_NEAR(velocityAt(v, 48, 32).y(), 2.0f, 1e-5f);
  EXPECT_NEAR(velocityAt(v, 32, 16).x(), 2.0f, 1e-5f);
  EXPECT_NEAR(velocityAt(v, 32, 16).y(), 0.0f, 1e-5f);
  // From 1: pixel 0 is 32 pixels from the centre either way round the torus.
  for (int y = 1; y < 64; y += 5)
    for (int x = 1; x < 64; x += 3) {
      const Vec2f d(float(x - 32), float(y - 32));
      EXPECT_NEAR(velocityAt(v, x, y).dot(d), 0.0f, 1e-4f) << x << "," << y;
      EXPECT_GE(d.x() * velocityAt(v, x, y).y() - d.y() * velocityAt(v, x, y).x(), 0.0f);  // clockwise on screen
    }
  EXPECT_EQ(velocityAt(v, 32, 32), Vec2f(0, 0));
}

TEST(ImageFlow, SourceSinkAndSaddleDirections) {
  const Image source = centred("source"), sink = centred("sink"), saddle = centred("saddle");
  EXPECT_NEAR(velocityAt(source, 48, 32).x(), 2.0f, 1e-5f);
  EXPECT_NEAR(velocityAt(source, 32, 16).y(), -2.0f, 1e-5f);
  for (int y = 1; y < 64; y += 7)
    for (int x = 1; x < 64; x += 5) {
      const Vec2f d(float(x - 32), float(y - 32));
      const Vec2f out = velocityAt(source, x, y);
      EXPECT_GE(out.dot(d), 0.0f);
      EXPECT_NEAR(out.x() * d.y() - out.y() * d.x(), 0.0f, 1e-4f);  // radial
      EXPECT_EQ(velocityAt(sink, x, y), Vec2f(-out));
    }
  // Out along x, in along y.
  EXPECT_GT(velocityAt(saddle, 48, 32).x(), 1.9f);
  EXPECT_GT(velocityAt(saddle, 16, 32).x(), -2.1f);
  EXPECT_LT(velocityAt(saddle, 16, 32).x(), -1.9f);
  EXPECT_LT(velocityAt(saddle, 32, 48).y(), -1.9f);
  EXPECT_GT(velocityAt(saddle, 32, 16).y(), 1.9f);
  EXPECT_GT(velocityAt(saddle, 40, 40).x(), 0.0f);
  EXPECT_LT(velocityAt(saddle, 40, 40).y(), 0.0f);
}

TEST(ImageFlow, SpeedPeaksAtTheRadiusAndFadesAtTheBorder) {
  const Image v = centred("vortex", 1.5f);
  int peak = 33;
  for (int x = 34; x < 64; ++x)
    if (velocityAt(v, x, 32).norm() > velocityAt(v, peak, 32).norm()) peak = x;
  EXPECT_EQ(peak, 48);
  EXPECT_NEAR(velocityAt(v, 48, 32).norm(), 1.5f, 1e-5f);
  // Formula check off the axes: r = 10, R = 16.
  const float s = std::hypot(6.0f, 8.0f) / 16.0f;
  EXPECT_NEAR(velocityAt(v, 38, 40).norm(), 1.5f * s * std::exp((1 - s * s) / 2), 1e-5f);
  // Default radius: under 7% of the strength anywhere on the border.
  const Image fading = ImageFlow::parse("source:strength=1", 96, 96).velocities(0);
  for (int i = 0; i < 96; ++i)
    for (const Vec2f& p : {velocityAt(fading, i, 0), velocityAt(fading, 0, i), velocityAt(fading, i, 95)})
      EXPECT_LT(p.norm(), 0.07f);
}

TEST(ImageFlow, DistancesWrapAroundTheTorus) {
  // Centre on the left border: pixels just inside the right border are just left of it.
  const Image v = ImageFlow::parse("source:cx=0,cy=0.5,radius=0.1", 40, 40).velocities(0);
  for (int d = 0; d < 6; ++d) {
    EXPECT_LT(velocityAt(v, 39 - d, 20).x(), 0.0f);
    EXPECT_EQ(velocityAt(v, 39 - d, 20).x(), -velocityAt(v, d, 20).x());
  }
}

TEST(ImageFlow, IdenticalForAnyThreadCount) {
  for (const char* spec : {"vortex:strength=3", "saddle:cx=0.2,cy=0.9,radius=0.3", "uniform:dx=0.25"}) {
    std::vector<float> one, many;
    {
      ThreadLimit limit(1);
      one = ImageFlow::parse(spec, 301, 97).velocities(0).pixels;
    }
    {
      ThreadLimit limit(3);
      many = ImageFlow::parse(spec, 301, 97).velocities(0).pixels;
    }
    EXPECT_EQ(one, many) << spec;
  }
}

TEST(ImageFlow, ExrVelocitiesAreReadExactly) {
  TempDir dir;
  const Image stored = exrVelocities(13, 9, 0.0f);
  writeImage(dir.file("v.exr"), stored);
  const ImageFlow flow = ImageFlow::parse(dir.file("v.exr"), 13, 9);
  EXPECT_EQ(flow.velocities(0).pixels, stored.pixels);
  EXPECT_FALSE(flow.timeVarying());
  EXPECT_EQ(flow.description(), "velocity image " + dir.file("v.exr"));
  const Image doubled = ImageFlow::parse(dir.file("v.exr"), 13, 9, {.scale = 2.0f}).velocities(0);
  for (std::size_t i = 0; i < stored.pixels.size(); ++i) EXPECT_EQ(doubled.pixels[i], 2.0f * stored.pixels[i]);
}

TEST(ImageFlow, IntegerImagesMapTwoCMinusOne) {
  TempDir dir;
  Image rgb(6, 4, 3);
  for (std::size_t i = 0; i < rgb.pixels.size(); ++i) rgb.pixels[i] = float((i * 37) % 256) / 255.0f;
  writeImage(dir.file("v.png"), rgb);
  const Image v = ImageFlow::parse(dir.file("v.png"), 6, 4).velocities(0);
  ASSERT_EQ(v.channels, 2);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x)
      for (int c = 0; c < 2; ++c) EXPECT_NEAR(v.at(x, y, c), 2 * rgb.at(x, y, c) - 1, 1e-6f);
}

TEST(ImageFlow, BadVelocityImagesNameTheFile) {
  TempDir dir;
  writeImage(dir.file("small.exr"), exrVelocities(8, 8, 0));
  expectInputError([&] { ImageFlow::parse(dir.file("small.exr"), 16, 16); }, dir.file("small.exr"),
                   "is 8x8, the output is 16x16");
  writeImage(dir.file("gray.png"), Image(16, 16, 1, 0.5f));
  expectInputError([&] { ImageFlow::parse(dir.file("gray.png"), 16, 16); }, dir.file("gray.png"),
                   "has 1 channel; a velocity image needs 2 (x, y)");
  expectInputError([&] { ImageFlow::parse(dir.file("missing.exr"), 16, 16); }, dir.file("missing.exr"));
  Image broken = exrVelocities(16, 16, 0);
  broken.at(5, 3, 1) = NAN;
  writeImage(dir.file("nan.exr"), broken);
  expectInputError([&] { ImageFlow::parse(dir.file("nan.exr"), 16, 16); }, dir.file("nan.exr"),
                   "velocity of nan at pixel (5, 3)");
}

TEST(ImageFlow, PatternsReadOneFilePerFrame) {
  TempDir dir;
  const Image first = exrVelocities(5, 4, 0.0f), second = exrVelocities(5, 4, 1.0f);
  writeImage(dir.file("f00.exr"), first);
  writeImage(dir.file("f01.exr"), second);
  const ImageFlow flow = ImageFlow::parse(dir.file("f%02d.exr"), 5, 4);
  EXPECT_TRUE(flow.timeVarying());
  EXPECT_EQ(flow.velocities(0).pixels, first.pixels);
  EXPECT_EQ(flow.velocities(1).pixels, second.pixels);
  flow.requireFrames(3);  // frames 0 and 1 move; frame 2 is the last
  expectInputError([&] { flow.requireFrames(4); }, dir.file("f02.exr"));
  expectInputError([&] { flow.velocities(2); }, dir.file("f02.exr"));
  writeImage(dir.file("f02.exr"), exrVelocities(4, 4, 0.0f));
  expectInputError([&] { flow.requireFrames(4); }, dir.file("f02.exr"), "is 4x4, the output is 5x4");
  // The first frame is read when parsing.
  expectInputError([&] { ImageFlow::parse(dir.file("g%d.exr"), 5, 4); }, dir.file("g0.exr"));
}

TEST(ImageFlow, BadSpecsAreFlowParameterErrors) {
  expectFlowError([] { ImageFlow::parse("vortx", 8, 8); },
                  "unknown preset 'vortx' (uniform, vortex, source, sink, saddle)");
  expectFlowError([] { ImageFlow::parse("vortex:strenght=1", 8, 8); }, "unknown key 'strenght'");
  expectFlowError([] { ImageFlow::parse("uniform:strength=1", 8, 8); }, "(dx, dy)");
  expectFlowError([] { ImageFlow::parse("vortex:strength=fast", 8, 8); }, "strength='fast' is not a finite number");
  expectFlowError([] { ImageFlow::parse("vortex:strength=nan", 8, 8); }, "not a finite number");
  expectFlowError([] { ImageFlow::parse("sink:strength=1e40", 8, 8); }, "not a finite number");
  expectFlowError([] { ImageFlow::parse("vortex:radius=0", 8, 8); }, "radius=0 is outside [0.001, 16]");
  expectFlowError([] { ImageFlow::parse("uniform:dx=5000", 8, 8); }, "dx=5000 is outside [-4096, 4096]");
  expectFlowError([] { ImageFlow::parse("vortex:cx=1.5", 8, 8); }, "cx=1.5 is outside [0, 1]");
  expectFlowError([] { ImageFlow::parse("saddle:cy=-0.1", 8, 8); }, "cy=-0.1 is outside [0, 1]");
  expectFlowError([] { ImageFlow::parse("vortex:cx=0.1,cx=0.2", 8, 8); }, "given twice");
  expectFlowError([] { ImageFlow::parse("vortex:cx", 8, 8); }, "'cx' is not key=value");
  expectFlowError([] { ImageFlow::parse("vortex:", 8, 8); }, "is not key=value");
  expectFlowError([] { ImageFlow::parse("", 8, 8); }, "empty");
  expectFlowError([] { ImageFlow::parse("flow/%s.exr", 8, 8); }, "frame number");
  expectFlowError([] { ImageFlow::parse("flow/%d_%d.exr", 8, 8); }, "more than one frame number");
}

TEST(ImageFlow, ScalesBeyondTheBoundAreScaleErrors) {
  for (const float scale : {INFINITY, 65.0f, -1e30f}) {
    try {
      ImageFlow::parse("vortex", 8, 8, {.scale = scale});
      ADD_FAILURE() << "accepted scale " << scale;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.parameter(), "flowScale");
    }
  }
  EXPECT_NO_THROW(ImageFlow::parse("uniform:dx=4096", 8, 8, {.scale = -64}));
}

TEST(ImageFlow, SpecificationsAreCheckedWithoutASizeOrMesh) {
  EXPECT_NO_THROW(checkFlowSpecification("vortex:strength=2"));
  EXPECT_NO_THROW(checkFlowSpecification("swirl:seed=7"));
  EXPECT_NO_THROW(checkFlowSpecification("flow/%04d.exr"));  // files are not opened
  expectFlowError([] { checkFlowSpecification("saddle:strength=1e30"); }, "outside");
  expectFlowError([] { checkFlowSpecification("swirl:seed=x"); }, "not a whole number");
  expectFlowError([] { checkFlowSpecification("flow/%x.exr"); }, "frame number");
  expectFlowError([] { checkFlowSpecification("twirl"); },
                  "in 2D: uniform, vortex, source, sink, saddle; on a mesh: "
                  "along-field, downhill, swirl");
}

TEST(ImageFlow, Descriptions) {
  EXPECT_EQ(ImageFlow::parse("vortex:radius=0.17", 8, 8).description(), "vortex strength 1 at (0.5, 0.5), radius 0.17");
  EXPECT_EQ(ImageFlow::parse("uniform:dy=2", 8, 8, {.scale = 0.5f}).description(),
            "uniform (1, 2) pixels per frame, scale 0.5");
}
