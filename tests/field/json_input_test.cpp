// JSON from user files (sketches, .tsfield headers): every way a document can be wrong is one
// InputError naming the file and the place, never a raw JSON exception (issue 13).
#include <gtest/gtest.h>

#include "field_test_support.h"
#include "texsynth/field/field_io.h"
#include "texsynth/field/sketch.h"

using namespace texsynth;

namespace {

void expectBadSketch(const std::string& json, const std::string& problem) {
  SCOPED_TRACE(json);
  test::expectInputError([&] { parseSketch(json, "s.json"); }, "s.json", problem);
}

// A .tsfield with the given header text and a zero body of `bodyBytes` bytes.
std::string fieldWithHeader(const std::string& header, std::size_t bodyBytes = 0) {
  std::string out = "TSFIELD1";
  for (int b = 0; b < 4; ++b) out.push_back(char((header.size() >> (8 * b)) & 0xff));
  return out + header + std::string(bodyBytes, '\0');
}

void expectBadField(const std::string& header, const std::string& problem) {
  SCOPED_TRACE(header);
  test::expectInputError([&] { decodeField(fieldWithHeader(header), "f.tsfield"); }, "f.tsfield", problem);
}

const std::string kLine = R"([0,0,0],[1,0,0])";

}  // namespace

TEST(JsonInput, SketchNumbersOutOfRangeNameTheFileAndPlace) {
  expectBadSketch(R"({"curves": [{"points": [[0,0,1e999],[1,0,0]]}]})",
                  "not valid JSON at line 1, column 34: number overflow parsing '1e999'");
  expectBadSketch("{\n\"curves\": [{\"points\": [\n[0,0,0],\n[-1e999,0,0]]}]}", "line 4, column 7");
  expectBadSketch(R"({"curves": [{"points": [[0,0,0],[1e39,0,0]]}]})",
                  "curves[0].points[1][0]: 1e+39 is not a finite single-precision number");
  expectBadSketch(
      R"({"curves": [{"points": [)" + kLine + R"(]}], "scale_points": [{"position": [0,0,0], "scale": 1e300}]})",
      "scale_points[0].scale: 1e+300 is not a finite");
  expectBadSketch(R"({"version": 1e999, "curves": []})", "number overflow");
  expectBadSketch(R"({"version": 18446744073709551617, "curves": []})", "version: must be an integer in [1, 1]");
}

TEST(JsonInput, SketchSyntaxAndTypeErrorsNameTheFileAndPlace) {
  expectBadSketch("{\n  \"curves\": [,]\n}", "not valid JSON at line 2, column 14: syntax error");
  expectBadSketch(R"({"curves": [{"points": [[0,0,"1"],[1,0,0]]}]})", "curves[0].points[0][2]: must be a number");
  expectBadSketch(R"({"curves": [{"points": [[0,0,null],[1,0,0]]}]})", "curves[0].points[0][2]: must be a number");
  expectBadSketch(R"({"version": "1", "curves": [{"points": [)" + kLine + "]}]}",
                  "version: must be an integer in [1, 1]");
  expectBadSketch(R"({"version": 1.0, "curves": [{"points": [)" + kLine + "]}]}", "version: must be an integer");
  expectBadSketch(R"({"version": 4294967297, "curves": [{"points": [)" + kLine + "]}]}", "version: must be");
  expectBadSketch(R"({"curves": [{"points": [)" + kLine + R"(], "name": 5}]})", "curves[0].name: must be a string");
  expectBadSketch("\xff", "not valid JSON at line 1");
}

TEST(JsonInput, ReadSketchNamesThePath) {
  test::TempDir dir;
  test::writeBytes(dir.file("s.json"), R"({"curves": [{"points": [[0,0,1e999],[1,0,0]]}]})");
  test::expectInputError([&] { readSketch(dir.file("s.json")); }, dir.file("s.json"), "number overflow");
}

TEST(JsonInput, FieldHeaderErrorsNameTheFileAndField) {
  const std::string good = R"("format":"texsynth-field","version":1,"origin":[0,0,0],"has_scale":false)";
  // Check the template first: with the right body it loads.
  std::string valid = "{" + good + R"(,"nodes":[2,2,2],"spacing":1})";
  std::string body;
  for (int i = 0; i < 8; ++i) body += std::string("\x00\x00\x80\x3f", 4) + std::string(12, '\0');  // w = 1
  ASSERT_NO_THROW(decodeField(fieldWithHeader(valid) + body, "f.tsfield"));

  expectBadField("{" + good + R"(,"nodes":[2,2,2],"spacing":1e999})",
                 "header: not valid JSON at line 1, column 105: number overflow parsing '1e999'");
  expectBadField("{" + good + R"(,"nodes":[2,2,1e10],"spacing":1})",
                 "header nodes[2]: must be an integer in [2, 4097]");
  expectBadField("{" + good + R"(,"nodes":[2,2,-5],"spacing":1})", "header nodes[2]: must be an integer");
  expectBadField("{" + good + R"(,"nodes":[2,2],"spacing":1})", "header \"nodes\": must be an array of 3 numbers");
  expectBadField("{" + good + R"(,"nodes":[2,2,2],"spacing":"1"})", "header spacing: must be a number");
  expectBadField("{" + good + R"(,"nodes":[2,2,2],"spacing":1e300})", "header spacing: 1e+300 is not a finite");
  expectBadField("{" + good + R"(,"nodes":[2,2,2],"spacing":-1})", "header spacing: must be positive");
  expectBadField("{" + good + R"(,"nodes":[2,2,2]})", "header has no \"spacing\"");
  expectBadField(
      R"({"format":"texsynth-field","version":1,"origin":[0,0,0],"has_scale":1,"nodes":[2,2,2],"spacing":1})",
      "header has_scale: must be true or false");
  expectBadField("[1, 2]", "header must be a JSON object");
}
