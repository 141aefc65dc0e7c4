#include "mesh_parse_support.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "texsynth/core/error.h"

namespace texsynth::mesh_detail {
namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// from_chars rejects a leading '+', which some writers emit.
std::string_view stripPlus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  return token;
}

template <class T>
bool parseWhole(std::string_view token, T& value, std::errc& error) {
  token = stripPlus(token);
  auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  error = ec;
  return ec == std::errc() && end == token.data() + token.size() && !token.empty();
}

}  // namespace

bool TextLines::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end < text_.size() ? end + 1 : end;
  ++line_;
  return true;
}

bool Tokens::next(std::string_view& token) {
  while (pos_ < line_.size() && isSpace(line_[pos_])) ++pos_;
  if (pos_ >= line_.size()) return false;
  std::size_t start = pos_;
  while (pos_ < line_.size() && !isSpace(line_[pos_])) ++pos_;
  token = line_.substr(start, pos_ - start);
  return true;
}

bool Tokens::atEnd() {
  while (pos_ < line_.size() && isSpace(line_[pos_])) ++pos_;
  return pos_ >= line_.size();
}

bool parseNumber(std::string_view token, float& value) {
  std::errc error;
  if (parseWhole(token, value, error)) return true;
  if (error != std::errc::result_out_of_range) return false;
  // Values below float's range (e.g. 1e-50) round to zero or a denormal; overflow is an error.
  double wide;
  if (!parseWhole(token, wide, error) || std::fabs(wide) > double(std::numeric_limits<float>::max())) return false;
  value = float(wide);
  return true;
}

bool parseNumber(std::string_view token, double& value) {
  std::errc error;
  return parseWhole(token, value, error);
}

bool parseNumber(std::string_view token, std::int64_t& value) {
  std::errc error;
  return parseWhole(token, value, error);
}

bool looksLikeInteger(std::string_view token) {
  token = stripPlus(token);
  if (!token.empty() && token[0] == '-') token.remove_prefix(1);
  if (token.empty()) return false;
  for (char c : token)
    if (c < '0' || c > '9') return false;
  return true;
}

void failAtLine(const std::string& source, int line, const std::string& problem) {
  throw InputError(source, "line " + std::to_string(line) + ": " + problem);
}

std::string quote(std::string_view token) {
  constexpr std::size_t kMaxShown = 24;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 32 && c < 127) {
      out += char(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > kMaxShown) out += "...";
  return out + "'";
}

void requirePlausibleCount(std::uint64_t count, std::uint64_t minBytesEach, std::uint64_t bytesLeft,
                           const std::string& what, const std::string& source, const std::string& where) {
  if (count > std::uint64_t(std::numeric_limits<int>::max()))
    throw InputError(source,
                     where + "declares " + std::to_string(count) + " " + what + ", more than a mesh index can address");
  if (minBytesEach > 0 && count > bytesLeft / minBytesEach)
    throw InputError(source, where + "declares " + std::to_string(count) + " " + what + " but only " +
                                 std::to_string(bytesLeft) + " bytes follow (at least " + std::to_string(minBytesEach) +
                                 " bytes each)");
}

void addPolygon(std::span<const int> polygon, std::vector<Vec3i>& triangles) {
  addPolygon(polygon, polygon, triangles);
}

void addPolygon(std::span<const int> polygon, std::span<const int> corners, std::vector<Vec3i>& triangles) {
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    int a = polygon[0], b = polygon[k], c = polygon[k + 1];
    if (a == b || b == c || a == c) continue;
    triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
  }
}

}  // namespace texsynth::mesh_detail
