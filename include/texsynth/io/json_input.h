#pragma once
// JSON read from a user's file (sketches, .tsfield headers, edit strokes).
// Every failure, whether bad syntax, a number beyond double's range, a wrong type or a
// non-finite value, becomes one InputError naming the file and where in it.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

#include "texsynth/core/math.h"

namespace texsynth::json_input {

// Parses `text`; a syntax error or an out-of-range number is an InputError(source, ...)
// with its line and column, after `part` when it is given ("header: not valid JSON ...").
nlohmann::json parse(std::string_view text, const std::string& source, const std::string& part = "");

// `where` names the value in messages (e.g. "curves[2].points[0]"); each throws
// InputError(source, where + ": " + problem) when the value is not what is asked for.
float finiteFloat(const nlohmann::json& value, const std::string& source, const std::string& where);
std::int64_t integerIn(const nlohmann::json& value, std::int64_t lo, std::int64_t hi, const std::string& source,
                       const std::string& where);

// The checks a strict file format makes of its objects, each failure an InputError naming `source` and
// the place: unknown keys are errors, so a typo never silently drops what it meant to say.
struct StrictReader {
  const std::string& source;

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const;
  // `object` is an object whose keys are all in `allowed`.
  void onlyKeys(const nlohmann::json& object, const std::string& where, const std::set<std::string>& allowed) const;
  // Three finite numbers.
  Vec3f vec3(const nlohmann::json& value, const std::string& where) const;
};

}  // namespace texsynth::json_input
