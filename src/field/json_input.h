#pragma once
// Internal to the field module: JSON read from a user's file (sketches, .tsfield headers).
// Every failure, whether bad syntax, a number beyond double's range, a wrong type or a
// non-finite value, becomes one InputError naming the file and where in it.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace texsynth::json_input {

// Parses `text`; a syntax error or an out-of-range number is an InputError(source, ...)
// with its line and column, after `part` when it is given ("header: not valid JSON ...").
nlohmann::json parse(std::string_view text, const std::string& source, const std::string& part = "");

// `where` names the value in messages (e.g. "curves[2].points[0]"); each throws
// InputError(source, where + ": " + problem) when the value is not what is asked for.
float finiteFloat(const nlohmann::json& value, const std::string& source, const std::string& where);
std::int64_t integerIn(const nlohmann::json& value, std::int64_t lo, std::int64_t hi, const std::string& source,
                       const std::string& where);

}  // namespace texsynth::json_input
