#pragma once
// Value streams over a PLY body: one for ascii tokens, one for binary data of either byte
// order. Both report where they are (element, item, line) when the data is bad or ends early.
// Internal to the io module; used by mesh_ply.cpp.
#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include "mesh_parse_support.h"
#include "mesh_ply_header.h"
#include "texsynth/core/error.h"

namespace texsynth::mesh_detail {

// What the reader is working on, for messages ("element 'face' item 12 of 100").
struct PlyPosition {
  const PlyElement* element = nullptr;
  std::uint64_t item = 0;
  std::string describe() const {
    if (!element) return "";
    return "element '" + element->name + "' item " + std::to_string(item) + " of " + std::to_string(element->count);
  }
};

class AsciiPlySource {
 public:
  static constexpr bool kBinary = false;
  AsciiPlySource(std::string_view bytes, const PlyHeader& header, const std::string& source)
      : lines_(bytes, header.bodyOffset), firstLine_(header.bodyFirstLine), source_(source) {}

  PlyPosition position;

  double value(PlyType type) {
    std::string_view token = nextToken();
    if (plyTypeIsInteger(type)) {
      std::int64_t integer;
      if (!parseNumber(token, integer)) fail("bad integer " + quote(token) + " in " + position.describe());
      return double(integer);
    }
    double real;
    if (!parseNumber(token, real)) fail("bad number " + quote(token) + " in " + position.describe());
    return real;
  }

  std::int64_t integer(PlyType type) {
    std::string_view token = nextToken();
    std::int64_t integer;
    if (!plyTypeIsInteger(type) || !parseNumber(token, integer))
      fail("bad integer " + quote(token) + " in " + position.describe());
    return integer;
  }

  void skipBytes(std::uint64_t) {}  // only binary sources skip by size

  [[noreturn]] void fail(const std::string& problem) const {
    failAtLine(source_, lines_.lineNumber() + firstLine_ - 1, problem);
  }

 private:
  std::string_view nextToken() {
    std::string_view token, line;
    while (!tokens_.next(token)) {
      if (!lines_.next(line)) {
        // Report the last line the file has, not one past it.
        throw InputError(source_, "line " + std::to_string(lines_.lineNumber() + firstLine_ - 1) +
                                      ": file ends inside " + position.describe());
      }
      tokens_ = Tokens(line);
    }
    return token;
  }

  TextLines lines_;
  Tokens tokens_{std::string_view()};
  int firstLine_;
  const std::string& source_;
};

class BinaryPlySource {
 public:
  static constexpr bool kBinary = true;
  BinaryPlySource(std::string_view bytes, const PlyHeader& header, const std::string& source)
      : bytes_(bytes),
        pos_(header.bodyOffset),
        swap_((header.format == PlyFormat::BinaryBigEndian) != (std::endian::native == std::endian::big)),
        source_(source) {}

  PlyPosition position;

  double value(PlyType type) {
    switch (type) {
      case PlyType::Int8:
        return load<std::int8_t>();
      case PlyType::UInt8:
        return load<std::uint8_t>();
      case PlyType::Int16:
        return load<std::int16_t>();
      case PlyType::UInt16:
        return load<std::uint16_t>();
      case PlyType::Int32:
        return load<std::int32_t>();
      case PlyType::UInt32:
        return load<std::uint32_t>();
      case PlyType::Float32:
        return load<float>();
      case PlyType::Float64:
        return load<double>();
    }
    return 0;
  }

  std::int64_t integer(PlyType type) {
    double v = value(type);
    if (!plyTypeIsInteger(type) && (!std::isfinite(v) || v != std::floor(v) || std::fabs(v) > 9e15))
      fail("non-integer index or count in " + position.describe());
    return std::int64_t(v);
  }

  void skipBytes(std::uint64_t count) {
    if (count > bytes_.size() - pos_) fail("file ends inside " + position.describe());
    pos_ += std::size_t(count);
  }

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(source_, problem); }

 private:
  template <class T>
  T load() {
    if (sizeof(T) > bytes_.size() - pos_) fail("file ends inside " + position.describe());
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    if (swap_)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  std::string_view bytes_;
  std::size_t pos_;
  bool swap_;
  const std::string& source_;
};

}  // namespace texsynth::mesh_detail
