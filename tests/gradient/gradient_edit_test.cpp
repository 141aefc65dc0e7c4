// Instant editing of gradient solids (§4.4): the fitted influence, the closed-form update of
// colours and gradients (eqs. 5-6), the raster baseline, and the stroke file format.
#include "texsynth/gradient/gradient_edit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/volume.h"
#include "texsynth/gradient/edit_influence.h"
#include "texsynth/gradient/gradient_solid.h"

using namespace texsynth;

namespace {

// A smooth colour field in [0.1, 0.9], different per channel.
double field(const Vec3f& p, int c) {
  return 0.5 + 0.3 * std::sin(0.15 * p.x() + 0.7 * c) * std::cos(0.11 * p.y() - 0.3 * c) +
         0.1 * std::sin(0.09 * p.z() + c);
}

// A solid whose control points sample `field` with its gradients (per cube edge).
GradientSolid smoothSolid(const Vec3i& voxels, int channels, int spacing = 4) {
  GradientSolid solid = GradientSolid::zeros(voxels, channels, spacing);
  for (int k = 0; k < solid.controls.z(); ++k)
    for (int j = 0; j < solid.controls.y(); ++j)
      for (int i = 0; i < solid.controls.x(); ++i) {
        float* set = &solid.positive[std::size_t(solid.controlIndex(i, j, k)) * std::size_t(solid.setSize())];
        const Vec3f p = Vec3f(float(i), float(j), float(k)) * float(spacing);
        for (int c = 0; c < channels; ++c) {
          set[c] = float(field(p, c));
          for (int a = 0; a < 3; ++a) {
            const Vec3f e = Vec3f::Unit(a) * 0.01f;
            set[(1 + a) * channels + c] = float((field(p + e, c) - field(p - e, c)) / 0.02 * spacing);
          }
        }
      }
  return solid;
}

std::vector<EditStroke> twoStrokes(float first, float second) {
  return {{{Vec3f(4, 6, 8), Vec3f(20, 10, 12), Vec3f(26, 24, 14)}, first},
          {{Vec3f(30, 30, 30), Vec3f(34, 20, 36)}, second}};
}

// The influence editGradientSolid fits for `strokes` (same voxels, colours and options).
EditInfluence influenceFor(const GradientSolid& solid, const std::vector<EditStroke>& strokes,
                           const EditOptions& options) {
  const StrokeVoxels voxels = rasterizeStrokes(strokes, solid.voxels);
  const int cc = editColorChannels(solid.channels);
  std::vector<float> colors;
  for (const Vec3i& v : voxels.positions) {
    float values[4];
    evaluateGradientSolid(solid, v.cast<float>(), {}, values);
    colors.insert(colors.end(), values, values + cc);
  }
  return fitEditInfluence(voxels, colors, cc, options);
}

}  // namespace

TEST(StrokeVoxels, PolylinesBecomeConnectedVoxelsLaterStrokesOverride) {
  const std::vector<EditStroke> strokes{{{Vec3f(2, 5, 5), Vec3f(10, 5, 5)}, 0.25f},
                                        {{Vec3f(6, 5, 5), Vec3f(6, 5, 7)}, 0.75f},
                                        {{Vec3f(-20, 1, 1), Vec3f(1, 1, 1)}, 1.0f}};
  const StrokeVoxels voxels = rasterizeStrokes(strokes, Vec3i(16, 16, 16));
  ASSERT_EQ(voxels.size(), 9 + 2 + 2);  // x = 2..10; (6,5,6), (6,5,7); (0,1,1), (1,1,1)
  for (int x = 2; x <= 10; ++x) {
    EXPECT_EQ(voxels.positions[std::size_t(x - 2)], Vec3i(x, 5, 5));
    EXPECT_EQ(voxels.strengths[std::size_t(x - 2)], x == 6 ? 0.75f : 0.25f);
  }
  EXPECT_EQ(voxels.positions.back(), Vec3i(1, 1, 1));
  test::expectParameterError([] { rasterizeStrokes({{{Vec3f(40, 0, 0)}, 1.0f}}, Vec3i(16, 16, 16)); }, "strokes");
  test::expectParameterError([] { rasterizeStrokes({}, Vec3i(16, 16, 16)); }, "strokes");
  test::expectParameterError([] { rasterizeStrokes({{{Vec3f(1, 1, 1)}, 1.5f}}, Vec3i(16, 16, 16)); }, "strokes");
}

TEST(GradientEdit, ZeroStrengthChangesNothing) {
  GradientSolid solid = smoothSolid(Vec3i(40, 40, 40), 3);
  const GradientSolid before = solid;
  const EditReport report = editGradientSolid(solid, twoStrokes(0.0f, 0.0f), EditOptions{});
  EXPECT_EQ(solid.positive, before.positive);  // bit-exact
  for (double w : report.weights) EXPECT_EQ(w, 0.0);
  EXPECT_EQ(report.strengthDeviation, 0.0);

  Volume volume = rasterizeGradientSolid(before);
  const Volume original = volume;
  editVolume(volume, twoStrokes(0.0f, 0.0f), EditOptions{});
  EXPECT_EQ(volume.voxels, original.voxels);
}

TEST(GradientEdit, FullStrengthTakesTheReferenceWhereZeroKeeps) {
  GradientSolid solid = smoothSolid(Vec3i(40, 40, 40), 3);
  const GradientSolid before = solid;
  EditOptions options;
  options.color = Vec3f(0.9f, 0.1f, 0.8f);
  options.alpha = 1e-3f;  // sharper than the paper's, so the two nearby strokes can differ
  options.beta = 5.0f;
  const std::vector<EditStroke> strokes = twoStrokes(1.0f, 0.0f);
  const EditReport report = editGradientSolid(solid, strokes, options);
  EXPECT_GT(report.strokeVoxels, 40);
  EXPECT_EQ(report.centres, options.centres);
  EXPECT_LT(report.strengthDeviation, 0.15);
  const StrokeVoxels voxels = rasterizeStrokes(strokes, solid.voxels);
  double towardsReference = 0, kept = 0;
  int strong = 0, weak = 0;
  for (int v = 0; v < voxels.size(); ++v) {
    float edited[3], original[3];
    evaluateGradientSolid(solid, voxels.positions[std::size_t(v)].cast<float>(), {}, edited);
    evaluateGradientSolid(before, voxels.positions[std::size_t(v)].cast<float>(), {}, original);
    double reference = 0, unchanged = 0;
    for (int c = 0; c < 3; ++c) {
      reference += std::abs(edited[c] - options.color[c]);
      unchanged += std::abs(edited[c] - original[c]);
    }
    if (voxels.strengths[std::size_t(v)] == 1.0f) {
      towardsReference += reference / 3;
      ++strong;
    } else {
      kept += unchanged / 3;
      ++weak;
    }
  }
  EXPECT_LT(towardsReference / strong, 0.08);
  EXPECT_LT(kept / weak, 0.08);
}

TEST(GradientEdit, InfluenceStaysInUnitRangeAndWeightsNonNegative) {
  GradientSolid solid = smoothSolid(Vec3i(40, 40, 40), 3);
  const GradientSolid before = solid;
  EditOptions options;
  options.color = Vec3f(0.0f, 1.0f, 0.2f);
  const EditReport report = editGradientSolid(solid, twoStrokes(1.0f, 0.6f), options);
  bool anyPositive = false;
  for (double w : report.weights) {
    EXPECT_GE(w, 0.0);
    anyPositive = anyPositive || w > 0;
  }
  EXPECT_TRUE(anyPositive);
  // c' = (1-h) c + h c_ref lies between c and c_ref exactly when h is in [0,1].
  for (std::size_t s = 0; s < solid.positive.size(); s += std::size_t(solid.setSize()))
    for (int c = 0; c < 3; ++c) {
      const float lo = std::min(before.positive[s + c], options.color[c]);
      const float hi = std::max(before.positive[s + c], options.color[c]);
      EXPECT_GE(solid.positive[s + c], lo - 1e-6f);
      EXPECT_LE(solid.positive[s + c], hi + 1e-6f);
    }
}

// Eqs. 5-6 against numeric derivatives of c'(p) = (1-h(p)) c(p) + h(p) c_ref, with c(p) the
// original solid and h(p) = min(1, sum w_k h_k(p, c(p))) from the continuous formula.
TEST(GradientEdit, GradientsMatchFiniteDifferences) {
  for (const bool paperParameters : {false, true}) {
    SCOPED_TRACE(paperParameters ? "alpha 1e-4, beta 0.1" : "alpha 1e-3, beta 0.5");
    GradientSolid solid = smoothSolid(Vec3i(40, 40, 40), 3);
    const GradientSolid before = solid;
    EditOptions options;
    options.color = Vec3f(0.2f, 0.9f, 0.4f);
    if (!paperParameters) {
      options.alpha = 1e-3f;
      options.beta = 0.5f;
    }
    const std::vector<EditStroke> strokes = twoStrokes(0.7f, 0.2f);
    const EditInfluence influence = influenceFor(before, strokes, options);
    const EditReport report = editGradientSolid(solid, strokes, options);
    ASSERT_EQ(report.weights, influence.weights);
    auto edited = [&](const Vec3f& p, int c) {
      float color[3];
      evaluateGradientSolid(before, p, {}, color);
      const double h = std::min(influence(p, color), 1.0);
      return (1 - h) * color[c] + h * options.color[c];
    };
    const float spacing = float(solid.spacing), step = 0.25f;
    double worst = 0, scale = 0;
    for (int k = 1; k + 1 < solid.controls.z(); k += 2)
      for (int j = 1; j + 1 < solid.controls.y(); j += 2)
        for (int i = 1; i + 1 < solid.controls.x(); i += 2) {
          const Vec3f p = Vec3f(float(i), float(j), float(k)) * spacing;
          const float* set = &solid.positive[std::size_t(solid.controlIndex(i, j, k)) * 12];
          for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(set[c], edited(p, c), 5e-4);  // colour tables interpolate
            for (int a = 0; a < 3; ++a) {
              const Vec3f e = Vec3f::Unit(a) * step;
              const double numeric = (edited(p + e, c) - edited(p - e, c)) / (2 * step);
              const double analytic = set[(1 + a) * 3 + c] / spacing;
              worst = std::max(worst, std::abs(numeric - analytic));
              scale = std::max(scale, std::abs(numeric));
            }
          }
        }
    EXPECT_GT(scale, 0.01);
    EXPECT_LT(worst, 0.02 * scale) << "largest derivative " << scale;
  }
}

TEST(GradientEdit, SameResultOnAnyThreadCount) {
  const GradientSolid original = smoothSolid(Vec3i(48, 40, 36), 3);
  GradientSolid one = original, many = original;
  const std::vector<EditStroke> strokes = twoStrokes(0.9f, 0.3f);
  {
    ThreadLimit limit(1);
    editGradientSolid(one, strokes, EditOptions{});
  }
  {
    ThreadLimit limit(4);
    editGradientSolid(many, strokes, EditOptions{});
  }
  EXPECT_EQ(one.positive, many.positive);
  EXPECT_NE(one.positive, original.positive);
}

TEST(GradientEdit, RegionsEditBothSidesAndKeepTheDistance) {
  GradientSolid solid = smoothSolid(Vec3i(40, 40, 40), 3);
  const std::size_t controls = std::size_t(solid.controlCount());
  solid.distance.assign(4 * controls, 0.0f);
  solid.negativeIndex.assign(controls, -1);
  for (std::size_t c = 0; c < controls; c += 3) {  // a negative set on every third control point
    solid.negativeIndex[c] = std::int32_t(solid.negative.size() / 12);
    for (int v = 0; v < 12; ++v) solid.negative.push_back(v < 3 ? 0.2f + 0.1f * float(v) : 0.01f * float(v));
  }
  for (std::size_t c = 0; c < controls; ++c) solid.distance[4 * c] = float(c % 7) - 3.0f;
  const GradientSolid before = solid;
  editGradientSolid(solid, twoStrokes(1.0f, 1.0f), EditOptions{});
  EXPECT_EQ(solid.distance, before.distance);
  EXPECT_EQ(solid.negativeIndex, before.negativeIndex);
  EXPECT_NE(solid.negative, before.negative);
  for (std::size_t s = 0; s < solid.negative.size(); s += 12)
    for (int c = 0; c < 3; ++c) {
      const float reference = EditOptions{}.color[c];
      EXPECT_LE(std::abs(solid.negative[s + c] - reference), std::abs(before.negative[s + c] - reference) + 1e-6f);
    }
}

TEST(GradientEdit, GraySolidsTakeTheReferenceLuminance) {
  GradientSolid solid = smoothSolid(Vec3i(32, 32, 32), 1);
  EditOptions options;
  options.color = Vec3f(1.0f, 0.0f, 0.0f);  // luminance 0.2126
  editGradientSolid(solid, {{{Vec3f(4, 4, 4), Vec3f(28, 28, 28)}, 1.0f}}, options);
  float value;
  evaluateGradientSolid(solid, Vec3f(16, 16, 16), {}, &value);
  EXPECT_NEAR(value, 0.2126f, 0.03f);
}

// The raster baseline with the same stroke colours fits the same weights; the two edits agree up
// to the control grid's approximation of the per-voxel edit.
TEST(GradientEdit, VolumeBaselineAgrees) {
  GradientSolid solid = smoothSolid(Vec3i(40, 40, 40), 3);
  Volume volume = rasterizeGradientSolid(solid);
  const std::vector<EditStroke> strokes = twoStrokes(0.8f, 0.3f);
  const EditReport onSolid = editGradientSolid(solid, strokes, EditOptions{});
  const EditReport onVolume = editVolume(volume, strokes, EditOptions{});
  ASSERT_EQ(onSolid.weights.size(), onVolume.weights.size());  // colours agree to float rounding
  for (std::size_t k = 0; k < onSolid.weights.size(); ++k) EXPECT_NEAR(onSolid.weights[k], onVolume.weights[k], 1e-4);
  EXPECT_EQ(onSolid.strokeVoxels, onVolume.strokeVoxels);
  const double rms = gradientSolidRms(solid, volume);
  EXPECT_LT(rms, 1.0) << "RMS on the 0..255 scale";
}

TEST(GradientEdit, BadParameters) {
  GradientSolid solid = smoothSolid(Vec3i(16, 16, 16), 3);
  const std::vector<EditStroke> strokes = twoStrokes(1.0f, 1.0f);
  EditOptions options;
  options.color = Vec3f(1.5f, 0, 0);
  test::expectParameterError([&] { editGradientSolid(solid, strokes, options); }, "color");
  options = {};
  options.centres = 0;
  test::expectParameterError([&] { editGradientSolid(solid, strokes, options); }, "centres");
  options = {};
  options.alpha = -1;
  test::expectParameterError([&] { editGradientSolid(solid, strokes, options); }, "alpha");
  test::expectParameterError([&] { editGradientSolid(solid, {}, EditOptions{}); }, "strokes");
  Volume empty;
  test::expectParameterError([&] { editVolume(empty, strokes, EditOptions{}); }, "volume");
}

TEST(StrokeFile, ReadsStrokesAndColour) {
  const EditStrokeFile file = parseEditStrokes(
      R"({"version": 1, "color": [0.5, 0.25, 1], "strokes": [
           {"points": [[1, 2, 3], [4, 5, 6]], "strength": 0.8}, {"points": [[7, 8, 9]]}]})",
      "s.json");
  ASSERT_EQ(file.strokes.size(), 2u);
  EXPECT_EQ(file.strokes[0].points[1], Vec3f(4, 5, 6));
  EXPECT_FLOAT_EQ(file.strokes[0].strength, 0.8f);
  EXPECT_EQ(file.strokes[1].strength, 1.0f);
  ASSERT_TRUE(file.color);
  EXPECT_EQ(*file.color, Vec3f(0.5f, 0.25f, 1.0f));
  EXPECT_FALSE(parseEditStrokes(R"({"strokes": [{"points": [[0, 0, 0]]}]})", "s.json").color);

  test::TempDir dir;
  test::writeBytes(dir.file("s.json"), R"({"strokes": [{"points": [[1, 1, 1]], "strength": 0}]})");
  EXPECT_EQ(readEditStrokes(dir.file("s.json")).size(), 1u);
  test::expectInputError([&] { readEditStrokes(dir.file("missing.json")); }, dir.file("missing.json"));
  test::writeBytes(dir.file("bad.json"), R"({"strokes": [{"points": [[1, 1]]}]})");
  test::expectInputError([&] { readEditStrokes(dir.file("bad.json")); }, dir.file("bad.json"), "strokes[0].points[0]");
}

TEST(StrokeFile, MalformedFilesNameTheJsonPath) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"{\"strokes\": [", "not valid JSON at line 1"},
      {"[1, 2]", "document: must be an object"},
      {"{}", "missing \"strokes\""},
      {R"({"strokes": {}})", "strokes: must be an array"},
      {R"({"strokes": []})", "strokes: needs at least 1 stroke"},
      {R"({"strokes": [{"points": []}]})", "strokes[0].points: needs at least 1 point"},
      {R"({"strokes": [{"strength": 1}]})", "strokes[0]: missing \"points\""},
      {R"({"strokes": [{"points": [[0,0,0]]}, 3]})", "strokes[1]: must be an object"},
      {R"({"strokes": [{"points": [[0,0,0]], "width": 2}]})", "strokes[0]: unknown key 'width'"},
      {R"({"strokes": [{"points": [[0,0,0]]}, {"points": [[0,0,0], [1,"a",0]]}]})", "strokes[1].points[1][1]"},
      {R"({"strokes": [{"points": [[0,0,0], [1e39,0,0]]}]})", "strokes[0].points[1][0]"},
      {R"({"strokes": [{"points": [[0,0,0]], "strength": 1.5}]})", "strokes[0].strength: must be in [0, 1]"},
      {R"({"strokes": [{"points": [[0,0,0]], "strength": "high"}]})", "strokes[0].strength: must be a number"},
      {R"({"strokes": [{"points": [[0,0,0]]}], "color": [1, 0]})", "color: must be an array of 3 numbers"},
      {R"({"strokes": [{"points": [[0,0,0]]}], "color": [1, 0, -0.5]})", "color[2]: must be in [0, 1]"},
      {R"({"strokes": [{"points": [[0,0,0]]}], "version": 2})", "version"},
      {R"({"strokes": [{"points": [[0,0,0]]}], "colour": [1, 0, 0]})", "unknown key 'colour'"},
  };
  for (const auto& [json, problem] : cases) {
    SCOPED_TRACE(json);
    test::expectInputError([&] { parseEditStrokes(json, "s.json"); }, "s.json", problem);
  }
}
