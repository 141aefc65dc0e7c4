#include "number_checks.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace texsynth::cli {

namespace {

// Shortest readable form of a bound: 0.5, 1e+06, 65536.
std::string bound(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

CLI::Validator finiteIn(double low, double high, bool highOpen) {
  const std::string range = "[" + bound(low) + ", " + bound(high) + (highOpen ? ")" : "]");
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return "'" + text + "' is not a number";
        if (!std::isfinite(value) || value < low || value > high || (highOpen && value == high))
          return "must be a finite number in " + range + ", got " + text;
        return {};
      },
      "NUMBER in " + range);
}

CLI::Validator integerIn(std::int64_t low, std::int64_t high) {
  const std::string range = "[" + std::to_string(low) + ", " + std::to_string(high) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        std::int64_t value = 0;
        const char* first = text.data() + (text.size() > 1 && text[0] == '+' ? 1 : 0);
        auto [end, ec] = std::from_chars(first, text.data() + text.size(), value);
        if (ec == std::errc::result_out_of_range) return "must be a whole number in " + range + ", got " + text;
        if (ec != std::errc() || end != text.data() + text.size()) return "'" + text + "' is not a whole number";
        if (value < low || value > high) return "must be a whole number in " + range + ", got " + text;
        return {};
      },
      "INT in " + range);
}

CLI::Validator unsigned64() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || ec != std::errc() || end != text.data() + text.size())
          return "must be a whole number in [0, 2^64 - 1], got " + text;
        return {};
      },
      "UINT64");
}

}  // namespace texsynth::cli
