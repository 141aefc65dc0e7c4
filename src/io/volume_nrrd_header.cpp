#include "volume_nrrd_header.h"

#include <algorithm>
#include <charconv>
#include <set>
#include <sstream>

#include "texsynth/core/error.h"

namespace texsynth::volume_codec {
namespace {

// Every field of NRRD0005, by canonical name; teem, too, refuses a header with any other.
const std::set<std::string>& knownFields() {
  static const std::set<std::string> fields = {"dimension",
                                               "type",
                                               "sizes",
                                               "encoding",
                                               "endian",
                                               "content",
                                               "min",
                                               "max",
                                               "oldmin",
                                               "oldmax",
                                               "spacings",
                                               "thicknesses",
                                               "axismins",
                                               "axismaxs",
                                               "centers",
                                               "labels",
                                               "units",
                                               "kinds",
                                               "space",
                                               "spacedimension",
                                               "spaceunits",
                                               "spaceorigin",
                                               "spacedirections",
                                               "measurementframe",
                                               "sampleunits",
                                               "blocksize",
                                               "datafile",
                                               "lineskip",
                                               "byteskip",
                                               "number"};
  return fields;
}

// "Data File" -> "datafile"; "centerings" is the older spelling of "centers".
std::string canonicalName(std::string_view name) {
  std::string out;
  for (char c : name)
    if (c != ' ' && c != '\t') out.push_back(char(std::tolower(static_cast<unsigned char>(c))));
  return out == "centerings" ? "centers" : out;
}

std::string trim(std::string_view s) {
  auto first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t\r");
  return first == std::string_view::npos ? std::string() : std::string(s.substr(first, last - first + 1));
}

// Kinds of an axis along which the samples are positions in space (or time) ...
bool isSpatialKind(const std::string& kind) {
  return kind == "domain" || kind == "space" || kind == "time" || kind == "???" || kind == "none";
}

// ... and the others, with the size their meaning fixes (0: any size). "???" / "none": unknown.
const std::map<std::string, std::int64_t>& valueKinds() {
  static const std::map<std::string, std::int64_t> kinds = {{"list", 0},
                                                            {"point", 0},
                                                            {"vector", 0},
                                                            {"covariant-vector", 0},
                                                            {"normal", 0},
                                                            {"stub", 1},
                                                            {"scalar", 1},
                                                            {"complex", 2},
                                                            {"2-vector", 2},
                                                            {"3-color", 3},
                                                            {"RGB-color", 3},
                                                            {"HSV-color", 3},
                                                            {"XYZ-color", 3},
                                                            {"4-color", 4},
                                                            {"RGBA-color", 4},
                                                            {"3-vector", 3},
                                                            {"3-gradient", 3},
                                                            {"3-normal", 3},
                                                            {"4-vector", 4},
                                                            {"quaternion", 4},
                                                            {"2D-symmetric-matrix", 3},
                                                            {"2D-masked-symmetric-matrix", 4},
                                                            {"2D-matrix", 4},
                                                            {"2D-masked-matrix", 5},
                                                            {"3D-symmetric-matrix", 6},
                                                            {"3D-masked-symmetric-matrix", 7},
                                                            {"3D-matrix", 9},
                                                            {"3D-masked-matrix", 10},
                                                            {"???", 0},
                                                            {"none", 0}};
  return kinds;
}

void checkKinds(const std::string& path, const std::vector<std::string>& kinds,
                const std::vector<std::int64_t>& sizes) {
  for (std::size_t axis = 0; axis < kinds.size(); ++axis) {
    const std::string& kind = kinds[axis];
    bool channelAxis = sizes.size() == 4 && axis == 0;
    std::string which = "NRRD 'kinds' says axis " + std::to_string(axis) + " is '" + kind + "'";
    if (!isSpatialKind(kind) && !valueKinds().count(kind)) throw InputError(path, which + ", an unknown kind");
    if (!channelAxis && !isSpatialKind(kind))
      throw InputError(path, which + ", but " +
                                 (sizes.size() == 3 ? std::string("a 3-D NRRD is a scalar volume (store channels as "
                                                                  "dimension 4 with sizes C X Y Z)")
                                                    : std::string("axes 1..3 of a 4-D NRRD must be spatial")));
    if (channelAxis && kind != "???" && kind != "none" && isSpatialKind(kind))
      throw InputError(path, which + ", but a 4-D NRRD must have its channel axis first (sizes C X Y Z)");
    if (channelAxis && valueKinds().at(kind) != 0 && valueKinds().at(kind) != sizes[0])
      throw InputError(path, which + ", which has " + std::to_string(valueKinds().at(kind)) +
                                 " values, but its size is " + std::to_string(sizes[0]));
  }
}

}  // namespace

const std::string& NrrdHeader::required(const std::string& path, const std::string& name) const {
  auto it = fields.find(name);
  if (it == fields.end()) throw InputError(path, "NRRD header has no '" + name + "' field");
  return it->second.value;
}

NrrdHeader parseNrrdHeader(const std::string& path, std::string_view bytes) {
  std::string_view magic = bytes.substr(0, bytes.find('\n'));
  if (!magic.empty() && magic.back() == '\r') magic.remove_suffix(1);
  if (magic.size() != 8 || magic.substr(0, 7) != "NRRD000" || magic[7] < '1' || magic[7] > '5')
    throw InputError(path, "not a NRRD file (its first line is not 'NRRD0001' .. 'NRRD0005')");
  NrrdHeader header;
  std::size_t at = 0;
  for (int lineNumber = 1;; ++lineNumber) {
    std::size_t end = bytes.find('\n', at);
    if (end == std::string_view::npos)
      throw InputError(path, "truncated: the NRRD header never ends (no blank line before the data)");
    std::string_view line = bytes.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    at = end + 1;
    if (lineNumber == 1 || (!line.empty() && line[0] == '#')) continue;
    if (line.empty()) break;
    std::string where = "NRRD header line " + std::to_string(lineNumber);
    std::size_t colon = line.find(':');
    if (colon == std::string_view::npos)
      throw InputError(path, "malformed " + where + ": '" + std::string(line.substr(0, 80)) + "'");
    if (colon + 1 < line.size() && line[colon + 1] == '=') continue;  // "key:=value" user data
    std::string name = canonicalName(line.substr(0, colon));
    if (!knownFields().count(name))
      throw InputError(path, where + " has the unknown field '" + trim(line.substr(0, colon)).substr(0, 80) +
                                 "' (custom data is written 'key:=value')");
    auto [it, inserted] = header.fields.emplace(name, NrrdField{trim(line.substr(colon + 1)), lineNumber});
    if (!inserted)
      throw InputError(path, where + " repeats the field '" + trim(line.substr(0, colon)) + "' of line " +
                                 std::to_string(it->second.line));
  }
  header.dataOffset = at;
  return header;
}

std::vector<std::string> nrrdWords(const std::string& value) {
  std::istringstream in(value);
  std::vector<std::string> out;
  for (std::string word; in >> word;) out.push_back(word);
  return out;
}

std::int64_t parseNrrdInteger(const std::string& path, const std::string& field, const std::string& text) {
  std::int64_t value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    throw InputError(path, "NRRD field '" + field + "' has a bad number '" + text + "'");
  return value;
}

void checkNrrdAxisFields(const std::string& path, const NrrdHeader& header, const std::vector<std::int64_t>& sizes) {
  for (const char* name : {"kinds", "spacings", "thicknesses", "axismins", "axismaxs", "centers"}) {
    if (!header.has(name)) continue;
    std::vector<std::string> entries = nrrdWords(header.fields.at(name).value);
    if (entries.size() != sizes.size())
      throw InputError(path, "NRRD '" + std::string(name) + "' (line " + std::to_string(header.fields.at(name).line) +
                                 ") lists " + std::to_string(entries.size()) + " axes, but the dimension is " +
                                 std::to_string(sizes.size()));
    if (std::string(name) == "kinds") checkKinds(path, entries, sizes);
  }
}

}  // namespace texsynth::volume_codec
