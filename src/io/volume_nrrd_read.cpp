// NRRD reader (teem's format, http://teem.sourceforge.net/nrrd/format.html): a text header of
// "field: value" lines ended by a blank line, then the samples, raw or gzip, fastest axis
// first. Only attached data is supported; every problem is one InputError naming the file.
#include <algorithm>
#include <bit>
#include <cstring>
#include <map>
#include <vector>

#include "texsynth/core/error.h"
#include "volume_codecs.h"
#include "volume_nrrd_header.h"

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

void rejectUnsupportedFields(const std::string& path, const NrrdHeader& header) {
  if (header.has("datafile"))
    throw InputError(path, "detached NRRD data ('data file: " + header.fields.at("datafile").value +
                               "') is not supported; store the samples in the .nrrd file itself");
  for (auto [name, spelled] : {std::pair{"lineskip", "line skip"}, std::pair{"byteskip", "byte skip"}})
    if (header.has(name) && parseNrrdInteger(path, spelled, header.fields.at(name).value) != 0)
      throw InputError(path, std::string("NRRD '") + spelled + "' is not supported");
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
  NrrdHeader header = parseNrrdHeader(path, bytes);
  rejectUnsupportedFields(path, header);

  const std::string& typeName = header.required(path, "type");
  auto type = sampleTypes().find(typeName);
  if (type == sampleTypes().end())
    throw InputError(path, "unsupported NRRD sample type '" + typeName +
                               "' (uint8, uint16, float, int8, int16, int32, uint32, double)");
  const SampleTypeInfo& sample = type->second;

  std::int64_t dimension = parseNrrdInteger(path, "dimension", header.required(path, "dimension"));
  if (dimension != 3 && dimension != 4)
    throw InputError(path,
                     "NRRD dimension " + std::to_string(dimension) + " is not a volume (need 3: X Y Z, or 4: C X Y Z)");
  std::vector<std::string> sizeWords = nrrdWords(header.required(path, "sizes"));
  if (std::int64_t(sizeWords.size()) != dimension)
    throw InputError(path, "NRRD 'sizes' lists " + std::to_string(sizeWords.size()) + " sizes for dimension " +
                               std::to_string(dimension));
  std::vector<std::int64_t> sizes;
  std::int64_t values = 1;
  std::string sizeText;
  for (const std::string& word : sizeWords) {
    std::int64_t size = parseNrrdInteger(path, "sizes", word);
    sizeText += (sizeText.empty() ? "" : "x") + word;
    if (size < 1 || size > 65536)
      throw InputError(path, "NRRD size " + word + " is absurd (each axis must be 1..65536)");
    sizes.push_back(size);
    values *= size;  // at most 2^47 before the check below fails
    if (values > (std::int64_t(1) << 31))
      throw InputError(path, "NRRD sizes " + std::string(sizeText) + "... are absurd (more than 2^31 values)");
  }
  checkNrrdAxisFields(path, header, sizes);
  if (header.has("number") && parseNrrdInteger(path, "number", header.fields.at("number").value) != values)
    throw InputError(path, "NRRD 'number: " + header.fields.at("number").value + "' disagrees with sizes " + sizeText +
                               " (" + std::to_string(values) + " samples)");

  std::string encoding = header.required(path, "encoding");
  bool gzip = encoding == "gzip" || encoding == "gz";
  if (!gzip && encoding != "raw") throw InputError(path, "unsupported NRRD encoding '" + encoding + "' (raw, gzip)");
  bool swapBytes = false;
  if (sample.bytes > 1) {
    auto endian = header.fields.find("endian");
    if (endian == header.fields.end())
      throw InputError(path, "NRRD header has no 'endian' field for " + typeName + " samples");
    if (endian->second.value != "little" && endian->second.value != "big")
      throw InputError(path, "unknown NRRD endian '" + endian->second.value + "'");
    swapBytes = (endian->second.value == "big") != (std::endian::native == std::endian::big);
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
  } else if (data.size() > needBytes) {
    throw InputError(path, what + " (" + std::to_string(needBytes) + " bytes) but " +
                               std::to_string(data.size() - needBytes) + " more bytes follow them");
  }

  int channels = dimension == 4 ? int(sizes[0]) : 1;
  std::size_t axis = dimension == 4 ? 1 : 0;
  Volume volume(int(sizes[axis]), int(sizes[axis + 1]), int(sizes[axis + 2]), channels);
  convert(sample, data.data(), volume.voxels.size(), swapBytes, volume.voxels.data());
  return volume;
}

}  // namespace texsynth::volume_codec
