// The sketch file format (docs/sketch-format.md): strict JSON, unknown keys rejected so a
// typo never silently drops a constraint.
#include <nlohmann/json.hpp>
#include <set>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/field/sketch.h"
#include "texsynth/io/json_input.h"

namespace texsynth {

namespace {

using nlohmann::json;

// Sketch files are small; anything larger is not one.
constexpr std::size_t kMaxSketchBytes = std::size_t(64) << 20;

struct Reader : json_input::StrictReader {
  int axis(const json& value, const std::string& where) const {
    if (value.is_string()) {
      std::string s = value.get<std::string>();
      if (s == "x") return 0;
      if (s == "y") return 1;
      if (s == "z") return 2;
    }
    fail(where, "must be \"x\", \"y\" or \"z\"");
  }
  std::string text(const json& value, const std::string& where) const {
    if (!value.is_string()) fail(where, "must be a string");
    return value.get<std::string>();
  }

  SketchCurve curve(const json& value, const std::string& where) const {
    onlyKeys(value, where, {"name", "points", "on", "mode", "plane", "tangent_axis", "normal_axis"});
    SketchCurve c;
    if (value.contains("name")) c.name = text(value["name"], where + ".name");
    if (!value.contains("points")) fail(where, "missing \"points\"");
    const json& points = value["points"];
    if (!points.is_array() || points.size() < 2) fail(where + ".points", "needs at least 2 points");
    for (std::size_t i = 0; i < points.size(); ++i) {
      c.points.push_back(vec3(points[i], where + ".points[" + std::to_string(i) + "]"));
      if (i > 0 && (c.points[i] - c.points[i - 1]).norm() <= 0)
        fail(where + ".points[" + std::to_string(i) + "]", "repeats the previous point");
    }
    std::string on = value.contains("on") ? text(value["on"], where + ".on") : "surface";
    if (on == "surface") {
      c.placement = CurvePlacement::Surface;
      if (value.contains("plane")) fail(where + ".plane", "only for curves with \"on\": \"plane\"");
    } else if (on == "plane") {
      c.placement = CurvePlacement::Plane;
      if (!value.contains("plane")) fail(where, "a plane curve needs \"plane\": {\"normal\": [x, y, z]}");
      const json& plane = value["plane"];
      onlyKeys(plane, where + ".plane", {"normal", "point"});
      if (!plane.contains("normal")) fail(where + ".plane", "missing \"normal\"");
      c.planeNormal = vec3(plane["normal"], where + ".plane.normal");
      if (!(c.planeNormal.norm() > 1e-12f)) fail(where + ".plane.normal", "must be non-zero");
      if (plane.contains("point")) c.planePoint = vec3(plane["point"], where + ".plane.point");
    } else {
      fail(where + ".on", "must be \"surface\" or \"plane\", got \"" + on + "\"");
    }
    std::string mode = value.contains("mode") ? text(value["mode"], where + ".mode") : "frame";
    if (mode == "frame")
      c.mode = CurveMode::Frame;
    else if (mode == "align")
      c.mode = CurveMode::Align;
    else
      fail(where + ".mode", "must be \"frame\" or \"align\", got \"" + mode + "\"");
    if (value.contains("tangent_axis")) c.tangentAxis = axis(value["tangent_axis"], where + ".tangent_axis");
    if (value.contains("normal_axis")) {
      if (c.mode == CurveMode::Align) fail(where + ".normal_axis", "only for \"frame\" curves");
      c.normalAxis = axis(value["normal_axis"], where + ".normal_axis");
    }
    if (c.tangentAxis && c.normalAxis && *c.tangentAxis == *c.normalAxis)
      fail(where, "tangent_axis and normal_axis must differ");
    return c;
  }
};

}  // namespace

const char* axisName(int axis) {
  static const char* names[] = {"x", "y", "z"};
  if (axis < 0 || axis > 2) throw ParameterError("axis", "must be 0, 1 or 2");
  return names[axis];
}

Sketch parseSketch(std::string_view text, const std::string& source) {
  const json document = json_input::parse(text, source);
  Reader reader{{source}};
  reader.onlyKeys(document, "sketch", {"version", "curves", "scale_points"});
  if (document.contains("version")) json_input::integerIn(document["version"], 1, 1, source, "version");
  if (!document.contains("curves") || !document["curves"].is_array() || document["curves"].empty())
    reader.fail("curves", "must be a non-empty array");
  Sketch sketch;
  const json& curves = document["curves"];
  for (std::size_t i = 0; i < curves.size(); ++i)
    sketch.curves.push_back(reader.curve(curves[i], "curves[" + std::to_string(i) + "]"));
  if (document.contains("scale_points")) {
    const json& points = document["scale_points"];
    if (!points.is_array()) reader.fail("scale_points", "must be an array");
    for (std::size_t i = 0; i < points.size(); ++i) {
      std::string where = "scale_points[" + std::to_string(i) + "]";
      reader.onlyKeys(points[i], where, {"position", "scale"});
      if (!points[i].contains("position") || !points[i].contains("scale"))
        reader.fail(where, "needs \"position\" and \"scale\"");
      ScalePoint p;
      p.position = reader.vec3(points[i]["position"], where + ".position");
      p.scale = json_input::finiteFloat(points[i]["scale"], source, where + ".scale");
      if (!(p.scale > 0)) reader.fail(where + ".scale", "must be positive");
      sketch.scalePoints.push_back(p);
    }
  }
  return sketch;
}

Sketch readSketch(const std::string& path) {
  return parseSketch(readFileBytes(path, kMaxSketchBytes), path);
}

std::string encodeSketch(const Sketch& sketch) {
  auto vec = [](const Vec3f& v) { return json::array({v.x(), v.y(), v.z()}); };
  json curves = json::array();
  for (const SketchCurve& c : sketch.curves) {
    json curve;
    if (!c.name.empty()) curve["name"] = c.name;
    curve["on"] = c.placement == CurvePlacement::Surface ? "surface" : "plane";
    curve["mode"] = c.mode == CurveMode::Frame ? "frame" : "align";
    if (c.placement == CurvePlacement::Plane) {
      curve["plane"]["normal"] = vec(c.planeNormal);
      if (c.planePoint) curve["plane"]["point"] = vec(*c.planePoint);
    }
    if (c.tangentAxis) curve["tangent_axis"] = axisName(*c.tangentAxis);
    if (c.normalAxis) curve["normal_axis"] = axisName(*c.normalAxis);
    curve["points"] = json::array();
    for (const Vec3f& p : c.points) curve["points"].push_back(vec(p));
    curves.push_back(curve);
  }
  json document{{"version", 1}, {"curves", curves}};
  if (!sketch.scalePoints.empty()) {
    document["scale_points"] = json::array();
    for (const ScalePoint& p : sketch.scalePoints)
      document["scale_points"].push_back({{"position", vec(p.position)}, {"scale", p.scale}});
  }
  return document.dump(2) + "\n";
}

}  // namespace texsynth
