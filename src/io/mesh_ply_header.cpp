#include "mesh_ply_header.h"

#include "mesh_parse_support.h"
#include "texsynth/core/error.h"

namespace texsynth::mesh_detail {
namespace {

bool parseType(std::string_view name, PlyType& type) {
  struct Named {
    std::string_view name;
    PlyType type;
  };
  static constexpr Named kTypes[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const Named& entry : kTypes)
    if (entry.name == name) {
      type = entry.type;
      return true;
    }
  return false;
}

// "ply", tolerating stray spaces around it.
bool isMagicLine(std::string_view line) {
  Tokens tokens(line);
  std::string_view word;
  return tokens.next(word) && word == "ply" && tokens.atEnd();
}

class PlyHeaderParser {
 public:
  PlyHeaderParser(std::string_view bytes, const std::string& source) : lines_(bytes), source_(source) {}

  PlyHeader parse() {
    std::string_view line, keyword;
    if (!lines_.next(line) || !isMagicLine(line))
      throw InputError(source_, "not a PLY file: it does not start with 'ply'");
    bool haveFormat = false;
    while (lines_.next(line)) {
      Tokens tokens(line);
      if (!tokens.next(keyword)) continue;
      if (keyword == "format") {
        readFormat(tokens);
        haveFormat = true;
      } else if (keyword == "element") {
        readElement(tokens);
      } else if (keyword == "property") {
        readProperty(tokens);
      } else if (keyword == "end_header") {
        if (!haveFormat) fail("header has no 'format' line");
        header_.bodyOffset = lines_.offset();
        header_.bodyFirstLine = lines_.lineNumber() + 1;
        checkCounts(lines_.bytesLeft());
        return std::move(header_);
      } else if (keyword != "comment" && keyword != "obj_info") {
        fail("unknown header keyword " + quote(keyword));
      }
    }
    throw InputError(source_, "header has no 'end_header' line (file truncated?)");
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { failAtLine(source_, lines_.lineNumber(), problem); }

  void readFormat(Tokens& tokens) {
    std::string_view name, version;
    if (!tokens.next(name) || !tokens.next(version)) fail("format line needs a format and a version");
    if (name == "ascii") {
      header_.format = PlyFormat::Ascii;
    } else if (name == "binary_little_endian") {
      header_.format = PlyFormat::BinaryLittleEndian;
    } else if (name == "binary_big_endian") {
      header_.format = PlyFormat::BinaryBigEndian;
    } else {
      fail("unknown format " + quote(name));
    }
    if (version != "1.0") fail("unsupported PLY version " + quote(version));
  }

  void readElement(Tokens& tokens) {
    std::string_view name, countToken;
    std::int64_t count;
    if (!tokens.next(name) || !tokens.next(countToken)) fail("element line needs a name and a count");
    if (!parseNumber(countToken, count) || count < 0) fail("bad element count " + quote(countToken));
    PlyElement element;
    element.name = std::string(name);
    element.count = std::uint64_t(count);
    element.line = lines_.lineNumber();
    header_.elements.push_back(std::move(element));
  }

  void readProperty(Tokens& tokens) {
    if (header_.elements.empty()) fail("property declared before any element");
    PlyProperty property;
    std::string_view typeName, name;
    if (!tokens.next(typeName)) fail("property line needs a type");
    if (typeName == "list") {
      std::string_view countName;
      property.isList = true;
      if (!tokens.next(countName) || !parseType(countName, property.countType))
        fail("bad list count type " + quote(countName));
      if (!plyTypeIsInteger(property.countType)) fail("list count type must be an integer type");
      if (!tokens.next(typeName)) fail("list property needs an item type");
    }
    if (!parseType(typeName, property.type)) fail("unknown property type " + quote(typeName));
    if (!tokens.next(name)) fail("property needs a name");
    property.name = std::string(name);
    header_.elements.back().properties.push_back(std::move(property));
  }

  // Every element must fit in what follows the header: absurd counts fail here, before any
  // allocation. +1 because the last ascii line may lack its newline.
  void checkCounts(std::uint64_t bodyBytes) const {
    std::uint64_t left = header_.format == PlyFormat::Ascii ? bodyBytes + 1 : bodyBytes;
    for (const PlyElement& element : header_.elements) {
      std::uint64_t each = element.minBytesPerItem(header_.format);
      std::string where = "line " + std::to_string(element.line) + ": element '" + element.name + "' ";
      requirePlausibleCount(element.count, each, left, "items", source_, where);
      left -= element.count * each;
    }
  }

  TextLines lines_;
  const std::string& source_;
  PlyHeader header_;
};

}  // namespace

int plyTypeSize(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

bool plyTypeIsInteger(PlyType type) {
  return type != PlyType::Float32 && type != PlyType::Float64;
}

int PlyElement::find(std::string_view propertyName) const {
  for (std::size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == propertyName) return int(i);
  return -1;
}

std::uint64_t PlyElement::minBytesPerItem(PlyFormat format) const {
  std::uint64_t bytes = 0;
  for (const PlyProperty& property : properties) {
    // Text: at least one digit and one separator per value; a list at least its count.
    if (format == PlyFormat::Ascii)
      bytes += 2;
    else
      bytes += std::uint64_t(plyTypeSize(property.isList ? property.countType : property.type));
  }
  return bytes;
}

PlyHeader parsePlyHeader(std::string_view bytes, const std::string& source) {
  return PlyHeaderParser(bytes, source).parse();
}

}  // namespace texsynth::mesh_detail
