// Stroke files for gradient-solid edits (docs/stroke-format.md): strict JSON, unknown keys rejected
// so a typo never silently drops a stroke or its strength.
#include <nlohmann/json.hpp>
#include <set>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/gradient/gradient_edit.h"
#include "texsynth/io/json_input.h"

namespace texsynth {
namespace {

using nlohmann::json;

// Stroke files are small; anything larger is not one.
constexpr std::size_t kMaxStrokeFileBytes = std::size_t(64) << 20;

struct StrokeReader : json_input::StrictReader {
  float unitFloat(const json& value, const std::string& where) const {
    const float v = json_input::finiteFloat(value, source, where);
    if (!(v >= 0.0f && v <= 1.0f)) fail(where, "must be in [0, 1], got " + value.dump());
    return v;
  }

  EditStroke stroke(const json& value, const std::string& where) const {
    onlyKeys(value, where, {"points", "strength"});
    if (!value.contains("points")) fail(where, "missing \"points\"");
    const json& points = value["points"];
    if (!points.is_array()) fail(where + ".points", "must be an array of [x, y, z] points");
    if (points.empty()) fail(where + ".points", "needs at least 1 point");
    EditStroke s;
    for (std::size_t i = 0; i < points.size(); ++i)
      s.points.push_back(vec3(points[i], where + ".points[" + std::to_string(i) + "]"));
    if (value.contains("strength")) s.strength = unitFloat(value["strength"], where + ".strength");
    return s;
  }
};

}  // namespace

EditStrokeFile parseEditStrokes(std::string_view text, const std::string& source) {
  const json document = json_input::parse(text, source);
  const StrokeReader reader{{source}};
  if (!document.is_object()) reader.fail("document", "must be an object with \"strokes\"");
  reader.onlyKeys(document, "document", {"version", "color", "strokes"});
  if (document.contains("version")) json_input::integerIn(document["version"], 1, 1, source, "version");
  EditStrokeFile file;
  if (document.contains("color")) {
    const Vec3f color = reader.vec3(document["color"], "color");
    for (int a = 0; a < 3; ++a)
      if (!(color[a] >= 0.0f && color[a] <= 1.0f))
        reader.fail("color[" + std::to_string(a) + "]", "must be in [0, 1], got " + document["color"][a].dump());
    file.color = color;
  }
  if (!document.contains("strokes")) reader.fail("document", "missing \"strokes\"");
  const json& strokes = document["strokes"];
  if (!strokes.is_array()) reader.fail("strokes", "must be an array of strokes");
  if (strokes.empty()) reader.fail("strokes", "needs at least 1 stroke");
  for (std::size_t i = 0; i < strokes.size(); ++i)
    file.strokes.push_back(reader.stroke(strokes[i], "strokes[" + std::to_string(i) + "]"));
  return file;
}

EditStrokeFile readEditStrokeFile(const std::string& path) {
  return parseEditStrokes(readFileBytes(path, kMaxStrokeFileBytes), path);
}

std::vector<EditStroke> readEditStrokes(const std::string& path) {
  return readEditStrokeFile(path).strokes;
}

}  // namespace texsynth
