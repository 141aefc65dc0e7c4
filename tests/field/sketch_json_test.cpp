// The sketch file format: what it accepts, what it rejects, and the shipped examples.
#include <gtest/gtest.h>

#include <filesystem>

#include "field_test_support.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/field/sketch.h"
#include "texsynth/io/mesh_io.h"

using namespace texsynth;

namespace {

const char* kValid = R"({
  "version": 1,
  "curves": [
    {"name": "a", "points": [[0, 0, 1], [1, 0, 1]], "tangent_axis": "y", "normal_axis": "x"},
    {"on": "plane", "plane": {"normal": [0, 0, 2], "point": [0, 0, 0.5]}, "mode": "frame",
     "points": [[0, 0, 0.5], [1, 1, 0.5], [1, 0.5, 0.5]]},
    {"mode": "align", "points": [[0, 1, 0], [1, 1, 0]], "tangent_axis": "z"}
  ],
  "scale_points": [{"position": [0.5, 0.5, 0.5], "scale": 2}]
})";

void expectRejected(const std::string& json, const std::string& problem) {
  SCOPED_TRACE(json);
  test::expectInputError([&] { parseSketch(json, "s.json"); }, "s.json", problem);
}

}  // namespace

TEST(SketchJson, ParsesEveryFieldAndRoundTrips) {
  Sketch s = parseSketch(kValid, "s.json");
  ASSERT_EQ(s.curves.size(), 3u);
  EXPECT_EQ(s.curves[0].name, "a");
  EXPECT_EQ(s.curves[0].tangentAxis, 1);
  EXPECT_EQ(s.curves[0].normalAxis, 0);
  EXPECT_EQ(s.curves[1].placement, CurvePlacement::Plane);
  EXPECT_EQ(s.curves[1].planeNormal, Vec3f(0, 0, 2));
  EXPECT_EQ(s.curves[2].mode, CurveMode::Align);
  ASSERT_EQ(s.scalePoints.size(), 1u);
  EXPECT_EQ(s.scalePoints[0].scale, 2.0f);
  Sketch again = parseSketch(encodeSketch(s), "again");
  ASSERT_EQ(again.curves.size(), 3u);
  EXPECT_EQ(again.curves[1].points, s.curves[1].points);
  EXPECT_EQ(again.curves[1].planePoint, s.curves[1].planePoint);
  EXPECT_EQ(again.curves[2].tangentAxis, 2);
}

TEST(SketchJson, RejectsMalformedDocumentsWithTheirPlace) {
  expectRejected("{", "not valid JSON");
  expectRejected("[]", "must be an object");
  expectRejected(R"({"curves": []})", "non-empty array");
  expectRejected(R"({"curves": [{"points": [[0,0,0]]}]})", "curves[0].points: needs at least 2 points");
  expectRejected(R"({"curves": [{"points": [[0,0,0],[0,0,0]]}]})", "repeats the previous point");
  expectRejected(R"({"curves": [{"points": [[0,0],[1,0,0]]}]})", "array of 3 numbers");
  expectRejected(R"({"curves": [{"pointz": [[0,0,0],[1,0,0]]}]})", "unknown key 'pointz'");
  expectRejected(R"({"curves": [{"points": [[0,0,0],[1,0,0]], "on": "air"}]})", "\"surface\" or \"plane\"");
  expectRejected(R"({"curves": [{"points": [[0,0,0],[1,0,0]], "on": "plane"}]})", "needs \"plane\"");
  expectRejected(R"({"curves": [{"points": [[0,0,0],[1,0,0]], "on": "plane", "plane": {"normal": [0,0,0]}}]})",
                 "non-zero");
  expectRejected(R"({"curves": [{"points": [[0,0,0],[1,0,0]], "tangent_axis": "w"}]})", "\"x\", \"y\" or \"z\"");
  expectRejected(R"({"curves": [{"points": [[0,0,0],[1,0,0]], "tangent_axis": "x", "normal_axis": "x"}]})",
                 "must differ");
  expectRejected(R"({"curves": [{"points": [[0,0,0],[1,0,0]], "mode": "snap"}]})", "\"frame\" or \"align\"");
  expectRejected(R"({"version": 2, "curves": [{"points": [[0,0,0],[1,0,0]]}]})", "version");
  expectRejected(R"({"curves": [{"points": [[0,0,0],[1,0,0]]}], "scale_points": [{"position": [0,0,0], "scale": 0}]})",
                 "must be positive");
  test::expectInputError([] { readSketch("/nonexistent/sketch.json"); }, "/nonexistent/sketch.json");
}

TEST(SketchJson, ShippedExamplesDesignFieldsOnTheirMeshes) {
  // The repository's examples/sketches/.
  const std::string examples = (std::filesystem::path(TEXSYNTH_EXAMPLES_DIR) / "sketches").string();
  for (const auto& [sketchName, meshName] :
       {std::pair{"bunny.json", "bunny00.off"}, std::pair{"cow.json", "cow.off"}}) {
    SCOPED_TRACE(sketchName);
    auto meshPath = cgalMesh(meshName);
    TS_REQUIRE_DATA(meshPath);
    Sketch sketch = readSketch(examples + "/" + sketchName);
    FieldDesignOptions options = test::smallGrid(12);
    options.grid.margin = 0.05f;
    FieldDesign design = designField(readMesh(*meshPath), sketch, options);
    EXPECT_EQ(design.updates.size(), sketch.curves.size());
    for (const CurveUpdate& u : design.updates) EXPECT_TRUE(u.solve.converged);
  }
}
