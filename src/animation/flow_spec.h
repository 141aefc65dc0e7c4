#pragma once
// What image and surface flows share: the SPEC syntax ("NAME" or "NAME:key=value,...", else a
// velocity file, whose frame numbers core's FramePattern reads) and velocity scaling. Internal
// to the animation module. Every problem with a SPEC is a ParameterError("flow", ...).
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace texsynth::flow_detail {

// A key a preset accepts and the range of its value (a whole number when `whole`).
struct PresetKey {
  std::string_view name;
  double low, high;
  bool whole = false;
};

// A preset's name and the keys it accepts.
struct PresetKeys {
  std::string_view name;
  std::initializer_list<PresetKey> keys;
};

// The presets of ImageFlow and SurfaceFlow.
std::span<const PresetKeys> imagePresets();
std::span<const PresetKeys> surfacePresets();

class FlowSpec {
 public:
  // A preset when the part before ':' is one of `presets`' names (keys checked against its
  // list, each at most once, each value in its key's range); else a file when SPEC looks like a path (it holds '/', '.'
  // or
  // '%', or names an existing file); else an unknown preset.
  static FlowSpec parse(const std::string& spec, std::span<const PresetKeys> presets);

  bool isFile() const { return file_; }
  // The preset's name, or the file (pattern) as given.
  const std::string& name() const { return name_; }

  // The value of `key` (checked by parse), or `fallback` when SPEC does not set it.
  float number(std::string_view key, float fallback) const;
  std::uint64_t integer(std::string_view key, std::uint64_t fallback) const;

  // Throws ParameterError("flow", "NAME: problem").
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  const std::string* find(std::string_view key) const;
  // Throws unless `text` is a value in `key`'s range.
  void check(const PresetKey& key, const std::string& text) const;

  std::string name_;
  bool file_ = false;
  std::vector<std::pair<std::string, std::string>> settings_;
};

// A number for descriptions: at most 3 significant digits ("0.167", "1", "2.5e+03").
std::string shortNumber(double value);

// Parses the whole of `text` (a leading '+' allowed) as a finite float.
bool parseFiniteFloat(std::string_view text, float& value);

// Multiplies every value by `scale` (requireFlowScale'd; the values within kMaxFlowSpeed, so
// nothing overflows).
void scaleVelocities(std::span<float> values, float scale);

}  // namespace texsynth::flow_detail
