#include "texsynth/io/json_input.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "texsynth/core/error.h"

namespace texsynth::json_input {
namespace {

using nlohmann::json;

// A SAX consumer that builds nothing and only remembers where parsing failed: nlohmann's
// exceptions carry a position for syntax errors but not for numbers out of range.
struct ErrorLocator : json::json_sax_t {
  std::size_t offset = 0;
  std::string message;

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string&, const json::exception& error) override {
    offset = position;
    message = error.what();
    return false;
  }
};

// "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error ..." ->
// "syntax error ...": the location is reported separately.
std::string plainMessage(std::string message) {
  if (message.starts_with("[json.exception.")) message.erase(0, message.find("] ") + 2);
  if (message.starts_with("parse error")) message.erase(0, message.find(": ") + 2);
  return message;
}

std::string lineAndColumn(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  std::string_view before = text.substr(0, offset);
  std::size_t lineStart = before.rfind('\n');
  std::size_t line = 1 + std::size_t(std::count(before.begin(), before.end(), '\n'));
  std::size_t column = lineStart == std::string_view::npos ? offset : offset - lineStart - 1;
  return "line " + std::to_string(line) + ", column " + std::to_string(std::max<std::size_t>(column, 1));
}

// The offending value for a message, cut short: a wrong value may be a whole array.
std::string quote(const json& value) {
  std::string text = value.dump();
  return text.size() <= 40 ? text : text.substr(0, 37) + "...";
}

}  // namespace

json parse(std::string_view text, const std::string& source, const std::string& part) {
  try {
    return json::parse(text);
  } catch (const json::exception& error) {
    ErrorLocator locator;
    json::sax_parse(text, &locator);
    if (locator.message.empty()) locator.message = error.what();  // not expected: both parse alike
    throw InputError(source, (part.empty() ? "" : part + ": ") + "not valid JSON at " +
                                 lineAndColumn(text, locator.offset) + ": " + plainMessage(locator.message));
  }
}

float finiteFloat(const json& value, const std::string& source, const std::string& where) {
  if (!value.is_number()) throw InputError(source, where + ": must be a number");
  double v = value.get<double>();
  if (!std::isfinite(v) || std::abs(v) > double(std::numeric_limits<float>::max()))
    throw InputError(source, where + ": " + quote(value) + " is not a finite single-precision number");
  return float(v);
}

std::int64_t integerIn(const json& value, std::int64_t lo, std::int64_t hi, const std::string& source,
                       const std::string& where) {
  std::string range = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (value.is_number_integer() && !value.is_number_unsigned()) {
    std::int64_t v = value.get<std::int64_t>();
    if (v >= lo && v <= hi) return v;
  } else if (value.is_number_unsigned()) {
    std::uint64_t v = value.get<std::uint64_t>();
    if (hi >= 0 && v <= std::uint64_t(hi) && std::int64_t(v) >= lo) return std::int64_t(v);
  }
  throw InputError(source, where + ": must be " + range + ", not " + quote(value));
}

void StrictReader::fail(const std::string& where, const std::string& problem) const {
  throw InputError(source, where + ": " + problem);
}

void StrictReader::onlyKeys(const nlohmann::json& object, const std::string& where,
                            const std::set<std::string>& allowed) const {
  if (!object.is_object()) fail(where, "must be an object");
  for (const auto& item : object.items())
    if (!allowed.count(item.key())) fail(where, "unknown key '" + item.key() + "'");
}

Vec3f StrictReader::vec3(const nlohmann::json& value, const std::string& where) const {
  if (!value.is_array() || value.size() != 3) fail(where, "must be an array of 3 numbers");
  Vec3f v;
  for (int a = 0; a < 3; ++a) v[a] = finiteFloat(value[a], source, where + "[" + std::to_string(a) + "]");
  return v;
}

}  // namespace texsynth::json_input
