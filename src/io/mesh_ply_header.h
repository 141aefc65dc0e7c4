#pragma once
// The header of a PLY file: format, and the elements with their typed properties in file
// order. Internal to the io module (mesh_ply.cpp reads the body it describes).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace texsynth::mesh_detail {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

int plyTypeSize(PlyType type);
bool plyTypeIsInteger(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // the item type for a list
  bool isList = false;
  PlyType countType = PlyType::UInt8;  // lists only
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;  // header line declaring it, for messages

  // Index of the property with this name, or -1.
  int find(std::string_view propertyName) const;
  // Fewest bytes one item can take in the body (lists counted as empty).
  std::uint64_t minBytesPerItem(PlyFormat format) const;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t bodyOffset = 0;  // first byte after "end_header\n"
  int bodyFirstLine = 0;       // line number of the first body line (ascii)
};

// Parses and checks the header; throws InputError(source, "line N: ...") on any problem,
// including element counts the remaining bytes could not possibly hold.
PlyHeader parsePlyHeader(std::string_view bytes, const std::string& source);

}  // namespace texsynth::mesh_detail
