#pragma once
// Shared pieces of the mesh readers: a line/token scanner that keeps line numbers for error
// messages, allocation-free number parsing (std::from_chars), count plausibility checks that
// run before anything is allocated, and polygon triangulation. Internal to the io module.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "texsynth/core/math.h"

namespace texsynth::mesh_detail {

// Walks text line by line ('\n', with an optional '\r' before it), counting from line 1.
class TextLines {
 public:
  explicit TextLines(std::string_view text, std::size_t start = 0) : text_(text), pos_(start) {}
  // Sets `line` to the next line without its terminator; false at the end of the text.
  bool next(std::string_view& line);
  // 1-based number of the line last returned by next() (0 before the first call).
  int lineNumber() const { return line_; }
  // Byte offset just past the line last returned.
  std::size_t offset() const { return pos_; }
  std::size_t bytesLeft() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

// Whitespace-separated tokens of one line.
class Tokens {
 public:
  explicit Tokens(std::string_view line) : line_(line) {}
  // Sets `token` to the next token; false when the line is used up.
  bool next(std::string_view& token);
  // True when only whitespace remains.
  bool atEnd();

 private:
  std::string_view line_;
  std::size_t pos_ = 0;
};

// Number parsing without locales or allocation. A leading '+' is accepted. Returns false
// unless the whole token is a number (of the requested kind, within range).
bool parseNumber(std::string_view token, float& value);
bool parseNumber(std::string_view token, double& value);
bool parseNumber(std::string_view token, std::int64_t& value);

// True if the token is written as an integer (no '.', exponent, inf or nan).
bool looksLikeInteger(std::string_view token);

// Throws InputError(source, "line N: problem").
[[noreturn]] void failAtLine(const std::string& source, int line, const std::string& problem);

// A short, printable quote of a token for error messages (truncated, control bytes escaped).
std::string quote(std::string_view token);

// Rejects a header count that cannot be real before anything is allocated: `count` items of
// at least `minBytesEach` bytes must fit in `bytesLeft`, and the count must fit an int index.
// `what` names the items ("vertices"); `where` prefixes the message ("line 2: " or "").
void requirePlausibleCount(std::uint64_t count, std::uint64_t minBytesEach, std::uint64_t bytesLeft,
                           const std::string& what, const std::string& source, const std::string& where);

// Appends a polygon (0-based indices) as a triangle fan around its first vertex, dropping
// triangles that repeat an index (degenerate).
void addPolygon(std::span<const int> polygon, std::vector<Vec3i>& triangles);
// The same fan over per-corner values (texture coordinate indices ...): appends `corners`' values
// for exactly the triangles addPolygon(polygon) keeps.
void addPolygon(std::span<const int> polygon, std::span<const int> corners, std::vector<Vec3i>& triangles);

}  // namespace texsynth::mesh_detail
