#include "texsynth/field/field_io.h"

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/io/json_input.h"

namespace texsynth {

namespace {

constexpr char kMagic[8] = {'T', 'S', 'F', 'I', 'E', 'L', 'D', '1'};
constexpr std::size_t kMaxHeader = 1 << 16;

void putFloat(std::string& out, float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  for (int b = 0; b < 4; ++b) out.push_back(char((bits >> (8 * b)) & 0xff));
}
std::uint32_t getU32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int b = 0; b < 4; ++b) v |= std::uint32_t(std::uint8_t(bytes[at + b])) << (8 * b);
  return v;
}
float getFloat(std::string_view bytes, std::size_t at) {
  std::uint32_t bits = getU32(bytes, at);
  float v;
  std::memcpy(&v, &bits, 4);
  return v;
}

}  // namespace

std::string encodeField(const FieldFile& field) {
  const FieldGrid& g = field.rotations.grid();
  nlohmann::json header{{"format", "texsynth-field"},
                        {"version", 1},
                        {"nodes", {g.nodes.x(), g.nodes.y(), g.nodes.z()}},
                        {"origin", {g.origin.x(), g.origin.y(), g.origin.z()}},
                        {"spacing", g.spacing},
                        {"has_scale", field.hasScale}};
  std::string text = header.dump();
  std::string out(kMagic, 8);
  std::uint32_t length = std::uint32_t(text.size());
  for (int b = 0; b < 4; ++b) out.push_back(char((length >> (8 * b)) & 0xff));
  out += text;
  for (const Quatf& q : field.rotations.rotations()) {
    putFloat(out, q.w());
    putFloat(out, q.x());
    putFloat(out, q.y());
    putFloat(out, q.z());
  }
  if (field.hasScale)
    for (float s : field.scales.scales()) putFloat(out, s);
  return out;
}

FieldFile decodeField(std::string_view bytes, const std::string& source) {
  if (bytes.size() < 12 || std::memcmp(bytes.data(), kMagic, 8) != 0)
    throw InputError(source, "not a texsynth field file (missing TSFIELD1 signature)");
  std::uint32_t length = getU32(bytes, 8);
  if (length > kMaxHeader || 12 + std::size_t(length) > bytes.size()) throw InputError(source, "truncated header");
  const nlohmann::json header = json_input::parse(bytes.substr(12, length), source, "header");
  if (!header.is_object()) throw InputError(source, "header must be a JSON object");
  auto entry = [&](const char* key) -> const nlohmann::json& {
    if (!header.contains(key)) throw InputError(source, std::string("header has no \"") + key + "\"");
    return header[key];
  };
  auto triple = [&](const char* key) -> const nlohmann::json& {
    const nlohmann::json& value = entry(key);
    if (!value.is_array() || value.size() != 3)
      throw InputError(source, std::string("header \"") + key + "\": must be an array of 3 numbers");
    return value;
  };
  if (entry("format") != "texsynth-field" || entry("version") != 1)
    throw InputError(source, "unsupported field format or version");
  FieldGrid grid;
  for (int a = 0; a < 3; ++a) {
    const std::string index = std::to_string(a) + "]";
    grid.nodes[a] = int(json_input::integerIn(triple("nodes")[a], 2, 4097, source, "header nodes[" + index));
    grid.origin[a] = json_input::finiteFloat(triple("origin")[a], source, "header origin[" + index);
  }
  grid.spacing = json_input::finiteFloat(entry("spacing"), source, "header spacing");
  if (!(grid.spacing > 0)) throw InputError(source, "header spacing: must be positive");
  if (!entry("has_scale").is_boolean()) throw InputError(source, "header has_scale: must be true or false");
  const bool hasScale = entry("has_scale").get<bool>();
  const std::size_t n = std::size_t(grid.nodeCount());
  const std::size_t expected = 12 + std::size_t(length) + n * 16 + (hasScale ? n * 4 : 0);
  if (bytes.size() < expected)
    throw InputError(source,
                     "truncated: " + std::to_string(bytes.size()) + " bytes, expected " + std::to_string(expected));
  if (bytes.size() > expected) throw InputError(source, "has trailing bytes after the field data");
  std::size_t at = 12 + length;
  std::vector<Quatf> rotations(n);
  for (std::size_t i = 0; i < n; ++i, at += 16) {
    Quatf q(getFloat(bytes, at), getFloat(bytes, at + 4), getFloat(bytes, at + 8), getFloat(bytes, at + 12));
    if (!q.coeffs().allFinite() || std::abs(q.squaredNorm() - 1) > 1e-3f)
      throw InputError(source, "node " + std::to_string(i) + " is not a unit quaternion");
    rotations[i] = q;
  }
  FieldFile field;
  field.rotations = RotationField(grid, std::move(rotations));
  field.hasScale = hasScale;
  if (hasScale) {
    std::vector<float> scales(n);
    for (std::size_t i = 0; i < n; ++i, at += 4) {
      scales[i] = getFloat(bytes, at);
      if (!(scales[i] > 0) || !std::isfinite(scales[i]))
        throw InputError(source, "node " + std::to_string(i) + " has a non-positive scale");
    }
    field.scales = ScaleField(grid, std::move(scales));
  } else {
    field.scales = ScaleField(grid, 1.0f);
  }
  return field;
}

void writeField(const std::string& path, const FieldFile& field) {
  writeFileAtomically(path, encodeField(field));
}

FieldFile readField(const std::string& path) {
  return decodeField(readFileBytes(path), path);
}

}  // namespace texsynth
