#include "flow_spec.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "texsynth/core/error.h"

namespace texsynth::flow_detail {
namespace {

[[noreturn]] void failSpec(const std::string& problem) {
  throw ParameterError("flow", problem);
}

std::string joined(std::span<const std::string_view> names) {
  std::string list;
  for (std::string_view name : names) list += (list.empty() ? "" : ", ") + std::string(name);
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
      std::vector<std::string_view> names;
      for (const PresetKeys& p : presets) names.push_back(p.name);
      failSpec("unknown preset '" + name + "' (" + joined(names) + ")");
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
    if (std::find(preset->keys.begin(), preset->keys.end(), key) == preset->keys.end())
      result.fail("unknown key '" + key + "' (" + joined(preset->keys) + ")");
    if (result.find(key)) result.fail("key '" + key + "' is given twice");
    result.settings_.emplace_back(key, value);
  }
  return result;
}

const std::string* FlowSpec::find(std::string_view key) const {
  for (const auto& [k, v] : settings_)
    if (k == key) return &v;
  return nullptr;
}

float FlowSpec::number(std::string_view key, float fallback) const {
  const std::string* text = find(key);
  if (!text) return fallback;
  float value = 0;
  if (!parseFiniteFloat(*text, value)) fail(std::string(key) + "='" + *text + "' is not a finite number");
  return value;
}

std::uint64_t FlowSpec::integer(std::string_view key, std::uint64_t fallback) const {
  const std::string* text = find(key);
  if (!text) return fallback;
  std::uint64_t value = 0;
  if (!parseWhole(*text, value)) fail(std::string(key) + "='" + *text + "' is not an integer in 0..2^64-1");
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

void requireFiniteScale(float scale) {
  if (!std::isfinite(scale)) failSpec("scale " + shortNumber(scale) + " is not finite");
}

void scaleVelocities(std::span<float> values, float scale) {
  if (scale == 1.0f) return;
  for (float& v : values) {
    v *= scale;
    if (!std::isfinite(v)) failSpec("scale " + shortNumber(scale) + " makes the velocities overflow");
  }
}

}  // namespace texsynth::flow_detail
