#include "flow_spec.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "texsynth/animation/flow_limits.h"
#include "texsynth/core/error.h"
#include "texsynth/core/frame_pattern.h"

namespace texsynth::flow_detail {
namespace {

[[noreturn]] void failSpec(const std::string& problem) {
  throw ParameterError("flow", problem);
}

// "a, b, c" of the items' names (presets or keys).
template <class Items>
std::string joinedNames(const Items& items) {
  std::string list;
  for (const auto& item : items) list += (list.empty() ? "" : ", ") + std::string(item.name);
  return list;
}

bool looksLikePath(const std::string& spec) {
  std::error_code ec;
  return spec.find_first_of("/.%") != std::string::npos || std::filesystem::is_regular_file(spec, ec);
}

// from_chars wants the whole token and rejects a leading '+'.
template <class T>
bool parseWhole(std::string_view text, T& value) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

FlowSpec FlowSpec::parse(const std::string& spec, std::span<const PresetKeys> presets) {
  if (spec.empty()) failSpec("empty; give a preset name or a velocity file");
  const std::size_t colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  const auto preset = std::find_if(presets.begin(), presets.end(), [&](const PresetKeys& p) { return p.name == name; });
  FlowSpec result;
  result.name_ = preset == presets.end() ? spec : name;
  if (preset == presets.end()) {
    if (!looksLikePath(spec)) {
      failSpec("unknown preset '" + name + "' (" + joinedNames(presets) + ")");
    }
    result.file_ = true;
    return result;
  }
  if (colon == std::string::npos) return result;
  const std::string_view settings = std::string_view(spec).substr(colon + 1);
  for (std::size_t start = 0; start <= settings.size();) {
    const std::size_t end = std::min(settings.find(',', start), settings.size());
    const std::string_view item = settings.substr(start, end - start);
    start = end + 1;
    const std::size_t equals = item.find('=');
    const std::string text(item), key(item.substr(0, std::min(equals, item.size())));
    if (equals == std::string_view::npos || equals == 0)
      result.fail("'" + text + "' is not key=value (in '" + spec + "')");
    const std::string value(item.substr(equals + 1));
    const auto known =
        std::find_if(preset->keys.begin(), preset->keys.end(), [&](const PresetKey& k) { return k.name == key; });
    if (known == preset->keys.end()) result.fail("unknown key '" + key + "' (" + joinedNames(preset->keys) + ")");
    if (result.find(key)) result.fail("key '" + key + "' is given twice");
    result.settings_.emplace_back(key, value);
    result.check(*known, value);
  }
  return result;
}

void FlowSpec::check(const PresetKey& key, const std::string& text) const {
  const auto bound = [&](double value) {
    if (key.whole) return std::to_string(std::uint64_t(value));
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return std::string(text);
  };
  // Built piecewise: GCC 12 warns falsely (-Wrestrict) on a chain of operator+ starting at a literal.
  std::string range = "[";
  range.append(bound(key.low)).append(", ").append(bound(key.high)).append("]");
  double value = 0;
  if (key.whole) {
    std::uint64_t whole = 0;
    if (!parseWhole(std::string_view(text), whole))
      fail(std::string(key.name) + "='" + text + "' is not a whole number in " + range);
    value = double(whole);
  } else {
    float number = 0;
    if (!parseFiniteFloat(text, number)) fail(std::string(key.name) + "='" + text + "' is not a finite number");
    value = number;
  }
  if (value < key.low || value > key.high) fail(std::string(key.name) + "=" + text + " is outside " + range);
}

const std::string* FlowSpec::find(std::string_view key) const {
  for (const auto& [k, v] : settings_)
    if (k == key) return &v;
  return nullptr;
}

float FlowSpec::number(std::string_view key, float fallback) const {
  const std::string* text = find(key);
  float value = fallback;
  if (text) parseFiniteFloat(*text, value);
  return value;
}

std::uint64_t FlowSpec::integer(std::string_view key, std::uint64_t fallback) const {
  const std::string* text = find(key);
  std::uint64_t value = fallback;
  if (text) parseWhole(std::string_view(*text), value);
  return value;
}

void FlowSpec::fail(const std::string& problem) const {
  failSpec(name_ + ": " + problem);
}

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

bool parseFiniteFloat(std::string_view text, float& value) {
  return parseWhole(text, value) && std::isfinite(value);
}

void scaleVelocities(std::span<float> values, float scale) {
  if (scale == 1.0f) return;
  for (float& v : values) v *= scale;
}

}  // namespace texsynth::flow_detail

namespace texsynth {

void requireFlowScale(float scale) {
  if (!std::isfinite(scale) || std::abs(scale) > kMaxFlowScale)
    throw ParameterError("flowScale", "must be a finite number in [-" + flow_detail::shortNumber(kMaxFlowScale) + ", " +
                                          flow_detail::shortNumber(kMaxFlowScale) + "], got " +
                                          flow_detail::shortNumber(scale));
}

void checkFlowSpecification(const std::string& spec) {
  using namespace flow_detail;
  const std::string name = spec.substr(0, spec.find(':'));
  const auto named = [&](std::span<const PresetKeys> presets) {
    return std::any_of(presets.begin(), presets.end(), [&](const PresetKeys& p) { return p.name == name; });
  };
  if (named(surfacePresets())) {
    FlowSpec::parse(spec, surfacePresets());
    return;
  }
  if (!named(imagePresets()) && !looksLikePath(spec))
    failSpec("unknown preset '" + name + "' (in 2D: " + joinedNames(imagePresets()) +
             "; on a mesh: " + joinedNames(surfacePresets()) + ")");
  const FlowSpec parsed = FlowSpec::parse(spec, imagePresets());  // a file, or "unknown preset"
  if (parsed.isFile()) FramePattern(parsed.name(), "flow");
}

}  // namespace texsynth
