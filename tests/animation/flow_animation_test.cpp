// Flow animation end to end, on images and on a mesh: no flow with a large lambda keeps every
// frame, a uniform integer flow shifts the frame exactly, frames do not depend on the thread
// count, lambda 0 gives independent frames, bad options and velocities are rejected.
#include <gtest/gtest.h>

#include "test_support.h"
#include "texsynth/animation/flow_advection.h"
#include "texsynth/animation/image_animation.h"
#include "texsynth/animation/surface_animation.h"
#include "texsynth/core/error.h"
#include "texsynth/core/mesh_weld.h"
#include "texsynth/core/parallel.h"
#include "texsynth/render/primitives.h"

namespace texsynth {
namespace {

constexpr int kSide = 48;

TextureOptimizationOptions smallOptions() {
  TextureOptimizationOptions options;
  options.levels = 2;
  options.neighborhoodSizes = {9, 5};
  return options;
}

struct ImageFixture {
  Image exemplar = test::makeTestPattern(40, 40);
  std::vector<ExemplarAnalysis> analyses;
  ExemplarAnalysis parallel = analyzeExemplar(exemplar);
  ImageFixture() {
    for (const AnalysisOptions& options : optimizationAnalysisOptions(smallOptions()))
      analyses.push_back(analyzeExemplar(exemplar, options));
  }
  ImageAnimator animator(float coherence) const {
    FlowAnimationOptions options;
    options.coherence = coherence;
    return ImageAnimator(analyses, &parallel, smallOptions(), options, kSide, kSide);
  }
};

const ImageFixture& imageFixture() {
  static const ImageFixture instance;
  return instance;
}

Image uniformFlow(int width, int height, float dx, float dy) {
  Image velocities(width, height, 2);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) velocities.pixel(x, y)[0] = dx, velocities.pixel(x, y)[1] = dy;
  return velocities;
}

// A flow that turns around the centre: the solver has work to do.
Image swirlFlow(int width, int height) {
  Image velocities(width, height, 2);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float rx = float(x) - width / 2.0f, ry = float(y) - height / 2.0f;
      velocities.pixel(x, y)[0] = -0.05f * ry, velocities.pixel(x, y)[1] = 0.05f * rx;
    }
  return velocities;
}

TEST(ImageAnimation, NoFlowWithLargeLambdaKeepsEveryFrame) {
  ImageAnimator animator = imageFixture().animator(1e6f);
  const Image first = animator.colors();
  for (int t = 0; t < 3; ++t) {
    animator.advance(uniformFlow(kSide, kSide, 0, 0));
    EXPECT_EQ(animator.colors().pixels, first.pixels) << "frame " << animator.frame();
    EXPECT_EQ(animator.statistics().keptFraction, 1.0);
    EXPECT_EQ(animator.statistics().temporalChange, 0.0);
  }
}

TEST(ImageAnimation, UniformIntegerFlowShiftsTheFrameExactly) {
  ImageAnimator animator = imageFixture().animator(1e6f);
  const Image before = animator.colors();
  const int dx = 3, dy = -2;
  animator.advance(uniformFlow(kSide, kSide, float(dx), float(dy)));
  const Image& after = animator.colors();
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      for (int c = 0; c < after.channels; ++c)
        ASSERT_EQ(after.pixel(x, y)[c], before.pixel((x - dx + kSide) % kSide, (y - dy + kSide) % kSide)[c])
            << "pixel " << x << "," << y;
}

TEST(ImageAnimation, SubPixelMotionAccumulates) {
  // Four steps of a quarter pixel move the texture by one pixel: positions keep the fractions.
  ImageAnimator animator = imageFixture().animator(1e6f);
  const Image before = animator.colors();
  for (int t = 0; t < 4; ++t) animator.advance(uniformFlow(kSide, kSide, 0.25f, 0));
  int shifted = 0;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      shifted += animator.colors().pixel(x, y)[0] == before.pixel((x + kSide - 1) % kSide, y)[0];
  EXPECT_GT(shifted, kSide * kSide * 95 / 100);
}

TEST(ImageAnimation, UniformSubPixelFlowMovesEveryPixelAlike) {
  // Seven steps of (1.3, 0.4) move the content by (9.1, 2.8): every pixel copies the exemplar
  // pixel of the one (9, 3) away and keeps the same remainder (-0.1, 0.2), so the frame is frame
  // 0 moved whole, patch edges included, and the exemplar regions it copies do not drift.
  ImageAnimator animator = imageFixture().animator(1e6f);
  const ExemplarPositions before = animator.positions();
  for (int t = 0; t < 7; ++t) animator.advance(uniformFlow(kSide, kSide, 1.3f, 0.4f));
  const ExemplarPositions& after = animator.positions();
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const std::size_t i = std::size_t(y * kSide + x);
      ASSERT_EQ(after.pixels[i], before.pixels[std::size_t((y + kSide - 3) % kSide * kSide + (x + kSide - 9) % kSide)])
          << "pixel " << x << "," << y;
      EXPECT_NEAR(after.offsets[i].x(), -0.1f, 1e-4f);
      EXPECT_NEAR(after.offsets[i].y(), 0.2f, 1e-4f);
    }
}

TEST(ImageAnimation, FramesDoNotDependOnTheThreadCount) {
  auto run = [](int threads) {
    ThreadLimit limit(threads);
    ImageAnimator animator = imageFixture().animator(0.1f);
    for (int t = 0; t < 3; ++t) animator.advance(swirlFlow(kSide, kSide));
    return animator.colors().pixels;
  };
  const std::vector<float> one = run(1);
  EXPECT_EQ(one, run(2));
  EXPECT_EQ(one, run(3));
}

TEST(ImageAnimation, TheSolverRepairsWhatTheFlowDistorts) {
  ImageAnimator animator = imageFixture().animator(0.1f);
  for (int t = 0; t < 3; ++t) animator.advance(swirlFlow(kSide, kSide));
  EXPECT_LT(animator.statistics().keptFraction, 1.0);  // some texture is replaced ...
  EXPECT_GT(animator.statistics().keptFraction, 0.3);  // ... most is carried along
}

TEST(ImageAnimation, LambdaZeroGivesIndependentFrames) {
  ImageAnimator animator = imageFixture().animator(0.0f);
  const Image first = animator.colors();
  animator.advance(uniformFlow(kSide, kSide, 0, 0));
  EXPECT_EQ(animator.statistics().keptFraction, 0.0);
  EXPECT_GT(animator.statistics().temporalChange, 1.0);  // even without any flow
  EXPECT_NE(animator.colors().pixels, first.pixels);
}

TEST(ImageAnimation, RejectsBadOptionsSizesAndVelocities) {
  const ImageFixture& f = imageFixture();
  FlowAnimationOptions bad;
  bad.coherence = -1;
  EXPECT_THROW(ImageAnimator(f.analyses, &f.parallel, smallOptions(), bad, kSide, kSide), ParameterError);
  bad = {};
  bad.iterations = 0;
  EXPECT_THROW(ImageAnimator(f.analyses, &f.parallel, smallOptions(), bad, kSide, kSide), ParameterError);
  EXPECT_THROW(ImageAnimator(f.analyses, &f.parallel, smallOptions(), {}, 50, kSide), ParameterError);
  ImageAnimator animator = f.animator(0.1f);
  EXPECT_THROW(animator.advance(uniformFlow(kSide / 2, kSide, 0, 0)), ParameterError);
  EXPECT_THROW(animator.advance(Image(kSide, kSide, 1)), ParameterError);
}

TEST(FlowAdvection, MeanColorChangeIsInEightBitLevels) {
  Image a(4, 4, 3), b(4, 4, 3);
  for (float& v : b.pixels) v = 1.0f / 255.0f;
  EXPECT_NEAR(meanColorChange(a, b), 1.0, 1e-6);
}

struct SurfaceFixture {
  Image exemplar = test::makeTestPattern(kSide, kSide);
  std::vector<ExemplarAnalysis> analyses;
  PreparedSurface surface;
  SurfaceFixture() {
    for (const AnalysisOptions& options : optimizationAnalysisOptions(smallOptions()))
      analyses.push_back(analyzeExemplar(exemplar, options));
    const Mesh cube = weldCoincidentVertices(makeBoxMesh(Vec3f::Zero(), Vec3f::Ones())).mesh;
    MeshHierarchyOptions hierarchy;
    hierarchy.vertices = 2000;
    hierarchy.levels = 2;
    surface = prepareSurface(buildMeshHierarchy(cube, hierarchy, "cube"), {}, smallOptions().neighborhoodSizes);
  }
  // A flow along each vertex's tangent, a third of a vertex spacing per frame.
  std::vector<Vec3f> tangentFlow() const {
    std::vector<Vec3f> flow = surface.levels.back().tangents;
    for (Vec3f& v : flow) v *= surface.hierarchy.levels.back().spacing / 3;
    return flow;
  }
};

const SurfaceFixture& surfaceFixture() {
  static const SurfaceFixture instance;
  return instance;
}

TEST(SurfaceAnimation, NoFlowWithLargeLambdaKeepsEveryFrame) {
  const SurfaceFixture& f = surfaceFixture();
  FlowAnimationOptions options;
  options.coherence = 1e6f;
  SurfaceAnimator animator(f.analyses, f.surface, smallOptions(), options);
  const std::vector<std::int32_t> first = animator.sources();
  const std::vector<Vec3f> still(first.size(), Vec3f::Zero());
  for (int t = 0; t < 2; ++t) {
    animator.advance(still);
    EXPECT_EQ(animator.sources(), first);
  }
}

TEST(SurfaceAnimation, FramesDoNotDependOnTheThreadCountAndTheTextureMoves) {
  const SurfaceFixture& f = surfaceFixture();
  auto run = [&](int threads) {
    ThreadLimit limit(threads);
    SurfaceAnimator animator(f.analyses, f.surface, smallOptions(), {});
    for (int t = 0; t < 3; ++t) animator.advance(f.tangentFlow());
    // A good share of the advected frame survives the repair (frame 0 is the k-coherence start,
    // not a fixed point of the E+M steps, so the first frames move more).
    EXPECT_GT(animator.statistics().keptFraction, 0.25) << animator.statistics().keptFraction;
    return animator.sources();
  };
  const std::vector<std::int32_t> one = run(1);
  EXPECT_EQ(one, run(2));
  SurfaceAnimator still(f.analyses, f.surface, smallOptions(), {});
  EXPECT_NE(one, still.sources());
  EXPECT_THROW(still.advance(std::vector<Vec3f>(3, Vec3f::Zero())), ParameterError);
}

}  // namespace
}  // namespace texsynth
