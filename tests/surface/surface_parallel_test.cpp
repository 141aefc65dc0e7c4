// The surface start (surface_parallel.h): a coherent copy of the exemplar costs nothing on a
// plane (continuous coordinates; whole pixels pay a floor) and is a fixed point of the
// correction, synthesis on a sphere is made of nearly coherent copies, a flat-background exemplar keeps its sparse
// features on a mesh with a part thinner than the neighbourhoods, and the finest level's histogram
// band keeps thin dark veins' share of the colors.
#include "texsynth/surface/surface_parallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/mesh_weld.h"
#include "texsynth/eval/histogram_distance.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/render/primitives.h"
#include "texsynth/surface/surface_synthesis.h"

using namespace texsynth;

namespace {

constexpr int kSide = 48;

ExemplarAnalysis analysisOf(const Image& exemplar, int levels) {
  AnalysisOptions options;
  options.levelCount = levels;
  options.neighborhoodSize = 5;
  options.similarCount = 4;
  return analyzeExemplar(exemplar, options);
}

PreparedSurface preparedOf(const Mesh& mesh, int vertices, int levels) {
  MeshHierarchyOptions options;
  options.vertices = vertices;
  options.levels = levels;
  const std::vector<int> sizes = {9};
  return prepareSurface(buildMeshHierarchy(mesh, options, "test mesh"), {}, sizes);
}

// The start's tests lay their neighbourhoods out on the retiled mesh itself: their synthetic
// meshes (a box, an icosphere's facets) have no relief below the pixel scale for the smoothing
// to remove, and each compares single runs whose outcome moves with any change to the geometry
// (smoothed, the thin-part and vein tests below fail on about as many of 10 seeds as unsmoothed:
// 8 and 7 / 3 and 3 / 4 and 2, the sphere 2 and 1; the sphere none of 12 unsmoothed since a
// refinement that joins the start is kept, surface_level_measures.h). surface_preparation_test.cpp
// tests the smoothing.
const SurfaceOrientation kAsRetiled{nullptr, {}, 0};

// Surface synthesis at small settings: two levels, neighbourhoods 9 then 5.
struct Synthesized {
  TextureOptimizationOptions options;
  std::vector<ExemplarAnalysis> analyses;
  PreparedSurface surface;
  SurfaceSynthesisResult result;

  Synthesized(const Image& exemplar, const Mesh& mesh, int vertices, const SurfaceStartOptions& start = {},
              float featureWeight = kSurfaceFeatureWeight) {
    options.levels = 2;
    options.neighborhoodSizes = {9, 5};
    for (const AnalysisOptions& analysisOptions : surfaceAnalysisOptions(exemplar, options, featureWeight))
      analyses.push_back(analyzeExemplar(exemplar, analysisOptions));
    MeshHierarchyOptions hierarchy;
    hierarchy.vertices = vertices;
    hierarchy.levels = options.levels;
    surface = prepareSurface(buildMeshHierarchy(mesh, hierarchy, "test mesh"), kAsRetiled, options.neighborhoodSizes);
    result = synthesizeSurface(analyses, surface, options, noProgress(), start);
  }
  // The same surface and analyses synthesized with other start options, or another seed.
  SurfaceSynthesisResult rerun(const SurfaceStartOptions& start) const {
    return synthesizeSurface(analyses, surface, options, noProgress(), start);
  }
  SurfaceSynthesisResult reseeded(std::uint64_t seed) const {
    TextureOptimizationOptions seeded = options;
    seeded.seed = seed;
    return synthesizeSurface(analyses, surface, seeded, noProgress());
  }
};

float median(std::vector<float> values) {
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
  return values[values.size() / 2];
}

TEST(SurfaceParallel, ACoherentCopyCostsNothingOnAPlaneAndIsAFixedPoint) {
  const ExemplarAnalysis analysis = analysisOf(test::makeTestPattern(kSide, kSide), 1);
  const PreparedSurface surface = preparedOf(test::squareGrid(8), 2000, 1);
  const MeshLevel& level = surface.hierarchy.levels.back();
  const PreparedSurfaceLevel& prepared = surface.levels.back();
  // The exemplar laid flat: exemplar x along t, y along -b, one pixel per vertex spacing, at a
  // sub-pixel offset (the retiled vertices fall between pixels anyway).
  std::vector<Vec2f> copy(level.mesh.vertexCount());
  for (std::size_t v = 0; v < copy.size(); ++v) {
    const Vec3f& t = prepared.tangents[v];
    const Vec3f b = level.mesh.normals[v].cross(t);
    const Vec3f& p = level.mesh.positions[v];
    const float x = p.dot(t) / level.spacing + 100.3f, y = -p.dot(b) / level.spacing + 100.7f;
    copy[v] = Vec2f(std::fmod(x, float(kSide)), std::fmod(y, float(kSide)));
  }
  const std::vector<float> continuous = stencilDistances(prepared.stencil, analysis, 0, copy);
  EXPECT_LT(*std::max_element(continuous.begin(), continuous.end()), 1e-12f);
  // The same copy in whole pixels pays a misregistration floor almost everywhere.
  const std::vector<Vec2f> whole = coordinatesOfPixels(pixelsOfCoordinates(copy, kSide, kSide), kSide);
  EXPECT_GT(median(stencilDistances(prepared.stencil, analysis, 0, whole)), 1e-3f);

  SurfaceParallelOptions options;
  options.usageWeight = 0;
  std::vector<Vec2f> corrected = copy;
  EXPECT_LT(correctSurfaceCoordinates(prepared.stencil, analysis, 0, options, corrected), 1e-12);
  EXPECT_EQ(corrected, copy);
}

// Smooth waves: a misregistration of a fraction of a pixel costs little, incoherence a lot.
Image wavesExemplar() {
  Image image(kSide, kSide, 3);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      image.at(x, y, 0) = 0.5f + 0.4f * std::sin(0.39f * float(x) + 0.8f * std::sin(0.26f * float(y)));
      image.at(x, y, 1) = 0.5f + 0.4f * std::sin(0.26f * float(x + 2 * y));
      image.at(x, y, 2) = 0.5f + 0.4f * std::cos(0.52f * float(y));
    }
  return image;
}

TEST(SurfaceParallel, SynthesisOnASphereIsMadeOfNearlyCoherentCopies) {
  const Image exemplar = wavesExemplar();
  const Synthesized run(exemplar, test::icosphere(3), 1500);
  const SurfaceStencil& stencil = run.surface.levels.back().stencil;
  // Four seeds: on this smooth exemplar the start's random patches may not join, and the
  // refinement that joins them must be kept (seed 4 stayed at 0.5x the shuffled distance before).
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const SurfaceSynthesisResult result = seed == 1 ? run.result : run.reseeded(seed);
    const float synthesized = median(stencilDistances(stencil, run.analyses.back(), 1, result.coordinates));
    // On a curved surface the tangent frames turn from vertex to vertex, so copies are nearly, not
    // exactly, coherent: far nearer than the same coordinates shuffled among the vertices.
    std::vector<Vec2f> shuffled = result.coordinates;
    std::rotate(shuffled.begin(), shuffled.begin() + std::ptrdiff_t(shuffled.size() / 3), shuffled.end());
    const float random = median(stencilDistances(stencil, run.analyses.back(), 1, shuffled));
    EXPECT_LT(synthesized, 0.25f * random)
        << "seed " << seed << ": synthesized " << synthesized << ", shuffled " << random;
  }
}

// A gray ground with short dark strokes, two pixels wide, on about 8% of it.
Image flatBackgroundExemplar() {
  Image image(kSide, kSide, 3, 0.62f);
  for (int stroke = 0; stroke < 10; ++stroke) {
    const int x0 = (stroke * 29 + 5) % kSide, y0 = (stroke * 17 + 11) % kSide;
    const bool across = stroke % 2 == 0;
    for (int i = 0; i < 10; ++i)
      for (int w = 0; w < 2; ++w) {
        const int x = (across ? x0 + i : x0 + w) % kSide, y = (across ? y0 + w : y0 + i) % kSide;
        std::fill_n(image.pixel(x, y), 3, 0.12f);
      }
  }
  return image;
}

double darkShare(std::span<const Vec3f> colors) {
  std::size_t dark = 0;
  for (const Vec3f& c : colors) dark += c.x() < 0.35f;
  return double(dark) / double(colors.size());
}

TEST(SurfaceParallel, AFlatBackgroundExemplarKeepsItsFeaturesOnAMeshWithAThinPart) {
  const Image exemplar = flatBackgroundExemplar();
  std::vector<Vec3f> exemplarColors;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) exemplarColors.emplace_back(exemplar.pixel(x, y)[0], 0.0f, 0.0f);
  const double expected = darkShare(exemplarColors);
  // A box and, beside it, an arm thinner than the 9-cell neighbourhoods (about 7 vertex
  // spacings around).
  Mesh mesh = weldCoincidentVertices(makeBoxMesh(Vec3f::Zero(), Vec3f::Ones())).mesh;
  const Mesh arm = weldCoincidentVertices(makeBoxMesh(Vec3f(1.3f, 0.47f, 0.47f), Vec3f(2.3f, 0.53f, 0.53f))).mesh;
  const auto offset = int(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), arm.positions.begin(), arm.positions.end());
  for (const Vec3i& t : arm.triangles) mesh.triangles.push_back(t + Vec3i::Constant(offset));
  mesh.normals.clear();
  mesh.computeNormals();

  const Synthesized run(exemplar, mesh, 6000);
  const PreparedSurface& surface = run.surface;
  const SurfaceSynthesisResult& result = run.result;
  const double share = darkShare(result.colors);
  EXPECT_GT(expected, 0.04);
  EXPECT_NEAR(share, expected, 0.3 * expected) << "exemplar " << expected << ", surface " << share;
  // The arm keeps features too.
  std::vector<Vec3f> armColors;
  const Mesh& finest = surface.finestMesh();
  for (std::size_t v = 0; v < finest.vertexCount(); ++v)
    if (finest.positions[v].x() > 1.2f) armColors.push_back(result.colors[v]);
  ASSERT_GT(armColors.size(), 50u);
  EXPECT_GT(darkShare(armColors), 0.3 * expected) << "arm " << darkShare(armColors);
}

// A light, softly varying ground crossed by thin dark veins, one pixel wide, on about 12% of it.
Image veinedExemplar() {
  Image image(kSide, kSide, 3);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const float ground = 0.7f + 0.08f * std::sin(0.31f * float(x) + 0.2f * float(y));
      const float vein = std::abs(std::sin(0.19f * float(x) + 0.9f * std::sin(0.13f * float(y))));
      const float value = vein < 0.1f ? 0.2f : ground;
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = value - 0.05f * float(c);
    }
  return image;
}

double histogramOf(const Image& exemplar, std::span<const Vec3f> colors) {
  Image output(int(colors.size()), 1, 3);
  for (std::size_t v = 0; v < colors.size(); ++v)
    for (int c = 0; c < 3; ++c) output.pixels[3 * v + std::size_t(c)] = colors[v][c];
  return histogramDistance(exemplar, output);
}

TEST(SurfaceParallel, TheFinestLevelsHistogramBandKeepsThinVeins) {
  // The band alone against neither band nor hold. (The hold is there for GIMP exemplars,
  // surface_parallel.h; on this synthetic one it does not help: at 8000 vertices with E+M,
  // histogram distance 0.0052 with the band alone, 0.0081 with the hold too.)
  const Image exemplar = veinedExemplar();
  SurfaceStartOptions plainOptions;
  plainOptions.finestHistogramBand = 0;
  plainOptions.finestHoldsUsagePaidMoves = false;
  plainOptions.finestRefineHistogramWeight = 0;
  plainOptions.refine = false;  // the start alone (cheaper, and the band is the start's)
  SurfaceStartOptions bandOptions = plainOptions;
  bandOptions.finestHistogramBand = SurfaceStartOptions{}.finestHistogramBand;
  const Synthesized plain(exemplar, test::icosphere(3), 1600, plainOptions, 0.0f);
  const SurfaceSynthesisResult band = plain.rerun(bandOptions);
  const double before = histogramOf(exemplar, plain.result.colors), after = histogramOf(exemplar, band.colors);
  EXPECT_LT(after, 0.85 * before) << "histogram distance " << before << " without, " << after << " with the band";
  // It steers only between near-equal matches: the result stays as coherent.
  const SurfaceStencil& stencil = plain.surface.levels.back().stencil;
  const float plainDistance = median(stencilDistances(stencil, plain.analyses.back(), 1, plain.result.coordinates));
  const float bandDistance = median(stencilDistances(stencil, plain.analyses.back(), 1, band.coordinates));
  EXPECT_LT(bandDistance, 1.25f * plainDistance + 1e-4f)
      << "median stencil distance " << plainDistance << " / " << bandDistance;
}

TEST(SurfaceParallel, TheFeatureChannelKeepsThinVeins) {
  // Colors alone against colors and the distance to the distinctive (vein) pixels, the start alone
  // (it does the corrections that thin veins out; the refinement doubles the test's time), without
  // the polish, whose histogram band is a second cure for the same loss.
  const Image exemplar = veinedExemplar();
  SurfaceStartOptions start;
  start.refine = false;
  start.finestPolishPasses = 0;
  const Synthesized features(exemplar, test::icosphere(3), 1600, start);
  std::vector<ExemplarAnalysis> colorAnalyses;
  for (const AnalysisOptions& analysisOptions : surfaceAnalysisOptions(exemplar, features.options, 0.0f))
    colorAnalyses.push_back(analyzeExemplar(exemplar, analysisOptions));
  const SurfaceSynthesisResult colors =
      synthesizeSurface(colorAnalyses, features.surface, features.options, noProgress(), start);
  EXPECT_EQ(colorAnalyses.back().channels(), 3);
  EXPECT_EQ(features.analyses.back().channels(), 4);
  const double without = histogramOf(exemplar, colors.colors);
  const double with = histogramOf(exemplar, features.result.colors);
  EXPECT_LT(with, 0.85 * without) << "histogram distance " << without << " without, " << with << " with";
}

TEST(SurfaceParallel, SurfaceAnalysisOptionsAddTheFeatureMaskOnlyWhereThereAreFeatures) {
  TextureOptimizationOptions options;
  for (const AnalysisOptions& analysis : surfaceAnalysisOptions(veinedExemplar(), options)) {
    EXPECT_FALSE(analysis.featureMask.empty());
    EXPECT_EQ(analysis.featureWeight, kSurfaceFeatureWeight);
  }
  for (const AnalysisOptions& analysis : surfaceAnalysisOptions(veinedExemplar(), options, 0.0f))
    EXPECT_TRUE(analysis.featureMask.empty());
  for (const AnalysisOptions& analysis : surfaceAnalysisOptions(Image(16, 16, 3, 0.5f), options))
    EXPECT_TRUE(analysis.featureMask.empty());
  EXPECT_THROW(surfaceAnalysisOptions(veinedExemplar(), options, -1.0f), ParameterError);
}

}  // namespace
