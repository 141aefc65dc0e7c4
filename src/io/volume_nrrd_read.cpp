// NRRD reader (teem's format, http://teem.sourceforge.net/nrrd/format.html): a text header of
// "field: value" lines ended by a blank line, then the samples, raw or gzip, fastest axis
// first. Only attached data is supported; every problem is one InputError naming the file.
#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <map>
#include <sstream>
#include <vector>

#include "texsynth/core/error.h"
#include "volume_codecs.h"

namespace texsynth::volume_codec {
namespace {

enum class SampleType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float, Double };

struct SampleTypeInfo {
  SampleType type;
  std::size_t bytes;
  float scale;  // integers are normalized by their maximum, like 8/16-bit images
};

// NRRD spells each type several ways ("uchar", "unsigned char", "uint8_t" ...).
const std::map<std::string, SampleTypeInfo>& sampleTypes() {
  static const std::map<std::string, SampleTypeInfo> types = [] {
    std::map<std::string, SampleTypeInfo> t;
    auto add = [&](std::initializer_list<const char*> names, SampleTypeInfo info) {
      for (const char* name : names) t[name] = info;
    };
    add({"signed char", "int8", "int8_t"}, {SampleType::Int8, 1, 1.0f / 127.0f});
    add({"uchar", "unsigned char", "uint8", "uint8_t"}, {SampleType::UInt8, 1, 1.0f / 255.0f});
    add({"short", "short int", "signed short", "signed short int", "int16", "int16_t"},
        {SampleType::Int16, 2, 1.0f / 32767.0f});
    add({"ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t"},
        {SampleType::UInt16, 2, 1.0f / 65535.0f});
    add({"int", "signed int", "int32", "int32_t"}, {SampleType::Int32, 4, float(1.0 / 2147483647.0)});
    add({"uint", "unsigned int", "uint32", "uint32_t"}, {SampleType::UInt32, 4, float(1.0 / 4294967295.0)});
    add({"float"}, {SampleType::Float, 4, 1.0f});
    add({"double"}, {SampleType::Double, 8, 1.0f});
    return t;
  }();
  return types;
}

struct NrrdHeader {
  std::map<std::string, std::string> fields;
  std::size_t dataOffset = 0;
};

std::string trim(std::string_view s) {
  auto first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t\r");
  return first == std::string_view::npos ? std::string() : std::string(s.substr(first, last - first + 1));
}

NrrdHeader parseHeader(const std::string& path, std::string_view bytes) {
  if (bytes.size() < 8 || bytes.substr(0, 7) != "NRRD000")
    throw InputError(path, "not a NRRD file (it does not start with 'NRRD000x')");
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
    std::size_t colon = line.find(':');
    if (colon == std::string_view::npos)
      throw InputError(path, "malformed NRRD header line " + std::to_string(lineNumber) + ": '" +
                                 std::string(line.substr(0, 80)) + "'");
    if (colon + 1 < line.size() && line[colon + 1] == '=') continue;  // "key:=value" user data
    std::string field = trim(line.substr(0, colon));
    std::transform(field.begin(), field.end(), field.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    header.fields[field] = trim(line.substr(colon + 1));
  }
  header.dataOffset = at;
  return header;
}

const std::string& required(const std::string& path, const NrrdHeader& header, const std::string& field) {
  auto it = header.fields.find(field);
  if (it == header.fields.end()) throw InputError(path, "NRRD header has no '" + field + "' field");
  return it->second;
}

std::vector<std::string> words(const std::string& value) {
  std::istringstream in(value);
  std::vector<std::string> out;
  for (std::string word; in >> word;) out.push_back(word);
  return out;
}

std::int64_t parseInteger(const std::string& path, const std::string& field, const std::string& text) {
  std::int64_t value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    throw InputError(path, "NRRD field '" + field + "' has a bad number '" + text + "'");
  return value;
}

void rejectUnsupportedFields(const std::string& path, const NrrdHeader& header) {
  for (const char* name : {"data file", "datafile"})
    if (header.fields.count(name))
      throw InputError(path, "detached NRRD data ('data file: " + header.fields.at(name) +
                                 "') is not supported; store the samples in the .nrrd file itself");
  for (const char* name : {"line skip", "lineskip", "byte skip", "byteskip"})
    if (header.fields.count(name) && parseInteger(path, name, header.fields.at(name)) != 0)
      throw InputError(path, std::string("NRRD '") + name + "' is not supported");
}

template <typename T>
void convertSamples(const char* src, std::size_t count, bool swapBytes, float scale, float* dst) {
  char bytes[sizeof(T)];
  for (std::size_t i = 0; i < count; ++i, src += sizeof(T)) {
    std::memcpy(bytes, src, sizeof(T));
    if (swapBytes) std::reverse(bytes, bytes + sizeof(T));
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    dst[i] = float(value) * scale;
  }
}

void convert(const SampleTypeInfo& info, const char* src, std::size_t count, bool swapBytes, float* dst) {
  switch (info.type) {
    case SampleType::Int8:
      return convertSamples<std::int8_t>(src, count, false, info.scale, dst);
    case SampleType::UInt8:
      return convertSamples<std::uint8_t>(src, count, false, info.scale, dst);
    case SampleType::Int16:
      return convertSamples<std::int16_t>(src, count, swapBytes, info.scale, dst);
    case SampleType::UInt16:
      return convertSamples<std::uint16_t>(src, count, swapBytes, info.scale, dst);
    case SampleType::Int32:
      return convertSamples<std::int32_t>(src, count, swapBytes, info.scale, dst);
    case SampleType::UInt32:
      return convertSamples<std::uint32_t>(src, count, swapBytes, info.scale, dst);
    case SampleType::Float:
      return convertSamples<float>(src, count, swapBytes, info.scale, dst);
    case SampleType::Double:
      return convertSamples<double>(src, count, swapBytes, info.scale, dst);
  }
}

}  // namespace

Volume decodeNrrd(const std::string& path, std::string_view bytes) {
  NrrdHeader header = parseHeader(path, bytes);
  rejectUnsupportedFields(path, header);

  const std::string& typeName = required(path, header, "type");
  auto type = sampleTypes().find(typeName);
  if (type == sampleTypes().end())
    throw InputError(path, "unsupported NRRD sample type '" + typeName +
                               "' (uint8, uint16, float, int8, int16, int32, uint32, double)");
  const SampleTypeInfo& sample = type->second;

  std::int64_t dimension = parseInteger(path, "dimension", required(path, header, "dimension"));
  if (dimension != 3 && dimension != 4)
    throw InputError(path,
                     "NRRD dimension " + std::to_string(dimension) + " is not a volume (need 3: X Y Z, or 4: C X Y Z)");
  std::vector<std::string> sizeWords = words(required(path, header, "sizes"));
  if (std::int64_t(sizeWords.size()) != dimension)
    throw InputError(path, "NRRD 'sizes' lists " + std::to_string(sizeWords.size()) + " sizes for dimension " +
                               std::to_string(dimension));
  std::vector<std::int64_t> sizes;
  std::int64_t values = 1;
  std::string sizeText;
  for (const std::string& word : sizeWords) {
    std::int64_t size = parseInteger(path, "sizes", word);
    sizeText += (sizeText.empty() ? "" : "x") + word;
    if (size < 1 || size > 65536)
      throw InputError(path, "NRRD size " + word + " is absurd (each axis must be 1..65536)");
    sizes.push_back(size);
    values *= size;  // at most 2^47 before the check below fails
    if (values > (std::int64_t(1) << 31))
      throw InputError(path, "NRRD sizes " + std::string(sizeText) + "... are absurd (more than 2^31 values)");
  }
  if (dimension == 4) {
    auto kinds = header.fields.count("kinds") ? words(header.fields.at("kinds")) : std::vector<std::string>{};
    if (!kinds.empty() && (kinds[0] == "domain" || kinds[0] == "space" || kinds[0] == "time"))
      throw InputError(
          path, "4D NRRD must have its channel axis first (sizes C X Y Z), but 'kinds' says the first axis is '" +
                    kinds[0] + "'");
  }

  std::string encoding = required(path, header, "encoding");
  bool gzip = encoding == "gzip" || encoding == "gz";
  if (!gzip && encoding != "raw") throw InputError(path, "unsupported NRRD encoding '" + encoding + "' (raw, gzip)");
  bool swapBytes = false;
  if (sample.bytes > 1) {
    auto endian = header.fields.find("endian");
    if (endian == header.fields.end())
      throw InputError(path, "NRRD header has no 'endian' field for " + typeName + " samples");
    if (endian->second != "little" && endian->second != "big")
      throw InputError(path, "unknown NRRD endian '" + endian->second + "'");
    swapBytes = (endian->second == "big") != (std::endian::native == std::endian::big);
  }

  std::uint64_t needBytes = std::uint64_t(values) * sample.bytes;
  std::string_view data = bytes.substr(header.dataOffset);
  std::string what = "header says " + sizeText + " " + typeName;
  std::string inflated;
  if (gzip) {
    // Deflate cannot compress better than ~1032:1, so a tiny file cannot hold a huge volume.
    if (needBytes > std::uint64_t(data.size()) * 1100 + 4096)
      throw InputError(path, what + " (" + std::to_string(needBytes) + " bytes) but only " +
                                 std::to_string(data.size()) + " bytes of gzip data, which cannot hold that much");
    inflated = inflateExactly(path, data, needBytes);
    data = inflated;
  } else if (data.size() < needBytes) {
    throw InputError(path, "truncated: " + what + " but only " + std::to_string(data.size()) + " bytes of data (need " +
                               std::to_string(needBytes) + ")");
  }

  int channels = dimension == 4 ? int(sizes[0]) : 1;
  std::size_t axis = dimension == 4 ? 1 : 0;
  Volume volume(int(sizes[axis]), int(sizes[axis + 1]), int(sizes[axis + 2]), channels);
  convert(sample, data.data(), volume.voxels.size(), swapBytes, volume.voxels.data());
  return volume;
}

}  // namespace texsynth::volume_codec
