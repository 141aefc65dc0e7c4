#pragma once
// Internal to the io module: the NRRD header (teem's format, "field: value" lines ended by a
// blank line), parsed strictly: an unknown or repeated field, or per-axis fields that
// disagree with the dimension or with each other, is an InputError naming the file.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace texsynth::volume_codec {

struct NrrdField {
  std::string value;
  int line = 0;
};

struct NrrdHeader {
  // Keyed by canonical name: lower case without spaces ("data file" -> "datafile").
  std::map<std::string, NrrdField> fields;
  std::size_t dataOffset = 0;  // first byte after the blank line

  bool has(const std::string& name) const { return fields.count(name) != 0; }
  // The value of a field that must be there.
  const std::string& required(const std::string& path, const std::string& name) const;
};

NrrdHeader parseNrrdHeader(const std::string& path, std::string_view bytes);

// Whitespace-separated words of a field value.
std::vector<std::string> nrrdWords(const std::string& value);
std::int64_t parseNrrdInteger(const std::string& path, const std::string& field, const std::string& text);

// Checks every per-axis field (kinds, spacings, centers ...) against `sizes`: one entry per
// axis; axes 1..3 of 4-D and all axes of 3-D data must be spatial kinds, and a 4-D file's
// first kind must be a non-spatial one whose size (RGB-color: 3 ...) matches sizes[0].
void checkNrrdAxisFields(const std::string& path, const NrrdHeader& header, const std::vector<std::int64_t>& sizes);

}  // namespace texsynth::volume_codec
