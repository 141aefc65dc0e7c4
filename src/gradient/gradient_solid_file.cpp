#include "texsynth/gradient/gradient_solid_file.h"

#include <zlib.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <string_view>

#include "gradient_quantization.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"

namespace texsynth {
namespace {

namespace gq = gradient_quantization;

constexpr char kMagic[8] = {'T', 'S', 'G', 'S', 'O', 'L', 'I', 'D'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uint32_t kFlagRegions = 1, kFlagDetail = 2;
constexpr std::uint64_t kHeaderBytes = 40;  // magic, version, voxels, spacing, channels, flags, negative sets
constexpr int kMaxVoxels = 65536, kMaxSpacing = 64, kMaxChannels = 4;

// Every size of a file follows from its header; computed before anything is read or allocated.
struct Layout {
  std::uint64_t controls = 0, negatives = 0;
  int channels = 0;
  bool regions = false, detail = false;

  std::uint64_t maskBytes() const { return regions ? (controls + 7) / 8 : 0; }
  static std::uint64_t arrayBytes(std::uint64_t sets, int channels) {
    return 12 * std::uint64_t(channels) + sets * 4 * std::uint64_t(channels);
  }
  std::uint64_t totalBytes() const {
    std::uint64_t total = kHeaderBytes + arrayBytes(controls, channels) + 4;  // + the CRC
    if (regions) total += maskBytes() + arrayBytes(controls, 1) + arrayBytes(negatives, channels);
    if (detail) total += arrayBytes(controls, channels);
    return total;
  }
};

std::uint64_t boundaryControls(const GradientSolid& solid) {
  std::uint64_t count = 0;
  for (std::int32_t index : solid.negativeIndex) count += index >= 0;
  return count;
}

Layout layoutOf(const GradientSolid& solid) {
  return {std::uint64_t(solid.controlCount()), boundaryControls(solid), solid.channels, solid.hasRegions(),
          solid.hasDetail()};
}

// The file keeps one negative set per boundary control point, in control order; a solid's sets may
// be in any order (or shared), so the writer and quantizeGradientSolid both use this order.
std::vector<float> negativeInControlOrder(const GradientSolid& solid) {
  const std::size_t setSize = std::size_t(solid.setSize());
  std::vector<float> sets;
  sets.reserve(std::size_t(boundaryControls(solid)) * setSize);
  for (std::int32_t index : solid.negativeIndex) {
    if (index < 0) continue;
    const auto from = solid.negative.begin() + std::ptrdiff_t(std::size_t(index) * setSize);
    sets.insert(sets.end(), from, from + std::ptrdiff_t(setSize));
  }
  return sets;
}

void canonicalizeNegative(GradientSolid& solid) {
  solid.negative = negativeInControlOrder(solid);
  std::int32_t next = 0;
  for (std::int32_t& index : solid.negativeIndex)
    if (index >= 0) index = next++;
}

// What the format can hold; a solid beyond it is the caller's mistake, not bad input.
void checkStorable(const GradientSolid& solid) {
  solid.checkConsistent();
  for (int a = 0; a < 3; ++a)
    if (solid.voxels[a] > kMaxVoxels)
      throw ParameterError("solid", "voxels must be at most " + std::to_string(kMaxVoxels) + " per axis");
  if (solid.spacing > kMaxSpacing) throw ParameterError("solid", "spacing must be at most 64");
}

void putU32(std::string& out, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) out.push_back(char((v >> (8 * b)) & 0xff));
}
void putFloat(std::string& out, float v) {
  putU32(out, std::bit_cast<std::uint32_t>(v));
}

void appendArray(std::string& out, const std::vector<float>& sets, int channels, bool nonNegative) {
  const std::size_t count = sets.size() / (4 * std::size_t(channels));
  const std::vector<gq::ChannelRange> ranges = gq::measure(sets.data(), count, channels, nonNegative);
  for (const gq::ChannelRange& range : ranges) {
    putFloat(out, range.lo);
    putFloat(out, range.hi);
    putFloat(out, range.g);
  }
  const std::size_t at = out.size();
  out.resize(at + sets.size());
  gq::encodeSets(sets.data(), count, channels, ranges, reinterpret_cast<std::uint8_t*>(out.data() + at));
}

void quantizeArray(std::vector<float>& sets, int channels, bool nonNegative) {
  const std::size_t count = sets.size() / (4 * std::size_t(channels));
  const std::vector<gq::ChannelRange> ranges = gq::measure(sets.data(), count, channels, nonNegative);
  std::vector<std::uint8_t> codes(sets.size());
  gq::encodeSets(sets.data(), count, channels, ranges, codes.data());
  gq::decodeSets(codes.data(), count, channels, ranges, sets.data());
}

std::uint32_t crcOf(std::string_view bytes) {
  uLong crc = crc32(0L, nullptr, 0);
  // zlib takes at most 4 GiB - 1 per call.
  for (std::size_t at = 0; at < bytes.size(); at += std::size_t(1) << 30) {
    const std::size_t length = std::min(bytes.size() - at, std::size_t(1) << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), uInt(length));
  }
  return std::uint32_t(crc);
}

// Little-endian reads that never run past the end: a short file is "truncated", whatever its length.
class Reader {
 public:
  Reader(std::string_view bytes, const std::string& where) : bytes_(bytes), where_(where) {}

  const std::uint8_t* take(std::uint64_t n, const char* what) {
    if (n > bytes_.size() - at_) throw InputError(where_, std::string("truncated in the ") + what);
    const auto* p = reinterpret_cast<const std::uint8_t*>(bytes_.data() + at_);
    at_ += std::size_t(n);
    return p;
  }
  std::uint32_t u32(const char* what) {
    const std::uint8_t* p = take(4, what);
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
  }
  std::int32_t i32(const char* what) { return std::bit_cast<std::int32_t>(u32(what)); }
  float f32(const char* what) { return std::bit_cast<float>(u32(what)); }
  std::size_t at() const { return at_; }

 private:
  std::string_view bytes_;
  std::size_t at_ = 0;
  const std::string& where_;
};

int readInRange(Reader& in, const std::string& where, const char* what, int lo, int hi) {
  const std::int32_t v = in.i32(what);
  if (v < lo || v > hi)
    throw InputError(where, std::string(what) + " " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "]");
  return v;
}

// The boundary control points' bitmask into negativeIndex (sets numbered in control order).
void readMask(Reader& in, const std::string& where, const Layout& layout, std::vector<std::int32_t>& negativeIndex) {
  const std::uint8_t* mask = in.take(layout.maskBytes(), "boundary mask");
  std::uint64_t count = 0;
  for (std::uint64_t i = 0; i < layout.maskBytes(); ++i) count += std::uint64_t(std::popcount(mask[i]));
  if (count != layout.negatives)
    throw InputError(where, "the boundary mask marks " + std::to_string(count) +
                                " control points but the header says " + std::to_string(layout.negatives) +
                                " negative sets");
  if (layout.controls % 8 != 0 && mask[layout.maskBytes() - 1] >> (layout.controls % 8) != 0)
    throw InputError(where, "the boundary mask marks control points past the last one");
  negativeIndex.assign(std::size_t(layout.controls), -1);
  std::int32_t next = 0;
  for (std::uint64_t i = 0; i < layout.controls; ++i)
    if (mask[i / 8] >> (i % 8) & 1) negativeIndex[std::size_t(i)] = next++;
}

void readArray(Reader& in, const std::string& where, const char* what, std::uint64_t sets, int channels,
               bool nonNegative, std::vector<float>& out) {
  std::vector<gq::ChannelRange> ranges(static_cast<std::size_t>(channels));
  for (int c = 0; c < channels; ++c) {
    gq::ChannelRange& range = ranges[std::size_t(c)];
    range.lo = in.f32(what), range.hi = in.f32(what), range.g = in.f32(what);
    const std::string channel = std::string(what) + " channel " + std::to_string(c) + ": ";
    if (!std::isfinite(range.lo) || !std::isfinite(range.hi) || !std::isfinite(range.g))
      throw InputError(where, channel + "quantization parameters are not finite");
    if (range.lo > range.hi) throw InputError(where, channel + "value range has lo > hi");
    if (range.g < 0) throw InputError(where, channel + "gradient bound is negative");
    if (nonNegative && range.lo < 0) throw InputError(where, channel + "a standard deviation cannot be negative");
  }
  const std::size_t setSize = 4 * std::size_t(channels), n = std::size_t(sets) * setSize;
  const std::uint8_t* codes = in.take(n, what);
  for (std::size_t i = 0; i < n; ++i)
    if (i % setSize >= std::size_t(channels) && codes[i] > gq::kGradientMaxCode)
      throw InputError(where, std::string(what) + ": gradient code " + std::to_string(codes[i]) + " is not used");
  out.resize(n);
  gq::decodeSets(codes, std::size_t(sets), channels, ranges, out.data());
}

}  // namespace

void quantizeGradientSolid(GradientSolid& solid) {
  checkStorable(solid);
  canonicalizeNegative(solid);
  quantizeArray(solid.positive, solid.channels, false);
  if (solid.hasRegions()) {
    quantizeArray(solid.distance, 1, false);
    quantizeArray(solid.negative, solid.channels, false);
  }
  if (solid.hasDetail()) quantizeArray(solid.detail, solid.channels, true);
}

std::string encodeGradientSolid(const GradientSolid& solid) {
  checkStorable(solid);
  const Layout layout = layoutOf(solid);
  std::string out(kMagic, sizeof kMagic);
  out.reserve(std::size_t(layout.totalBytes()));
  putU32(out, kVersion);
  for (int a = 0; a < 3; ++a) putU32(out, std::uint32_t(solid.voxels[a]));
  putU32(out, std::uint32_t(solid.spacing));
  putU32(out, std::uint32_t(solid.channels));
  putU32(out, (layout.regions ? kFlagRegions : 0) | (layout.detail ? kFlagDetail : 0));
  putU32(out, std::uint32_t(layout.negatives));
  if (layout.regions) {
    std::string mask(std::size_t(layout.maskBytes()), '\0');
    for (std::size_t i = 0; i < solid.negativeIndex.size(); ++i)
      if (solid.negativeIndex[i] >= 0) mask[i / 8] = char(std::uint8_t(mask[i / 8]) | 1u << (i % 8));
    out += mask;
  }
  appendArray(out, solid.positive, solid.channels, false);
  if (layout.regions) {
    appendArray(out, solid.distance, 1, false);
    appendArray(out, negativeInControlOrder(solid), solid.channels, false);
  }
  if (layout.detail) appendArray(out, solid.detail, solid.channels, true);
  putU32(out, crcOf(out));
  TS_CHECK(out.size() == layout.totalBytes());
  return out;
}

GradientSolid decodeGradientSolid(const std::string& bytes, const std::string& where) {
  const std::size_t magicBytes = std::min(bytes.size(), sizeof kMagic);
  if (std::memcmp(bytes.data(), kMagic, magicBytes) != 0)
    throw InputError(where, "not a gradient solid file (no TSGSOLID signature)");
  Reader in(bytes, where);
  in.take(sizeof kMagic, "signature");
  const std::uint32_t version = in.u32("version");
  if (version != kVersion)
    throw InputError(where, "unsupported .tsgs version " + std::to_string(version) + " (this texsynth reads " +
                                std::to_string(kVersion) + ")");
  GradientSolid solid;
  for (int a = 0; a < 3; ++a) solid.voxels[a] = readInRange(in, where, "voxels", 1, kMaxVoxels);
  solid.spacing = readInRange(in, where, "spacing", 1, kMaxSpacing);
  solid.channels = readInRange(in, where, "channels", 1, kMaxChannels);
  const std::uint32_t flags = in.u32("flags");
  if (flags & ~(kFlagRegions | kFlagDetail)) throw InputError(where, "unknown flags " + std::to_string(flags));
  for (int a = 0; a < 3; ++a) solid.controls[a] = GradientSolid::controlsFor(solid.voxels[a], solid.spacing);

  // The header's sizes against the file's before any allocation; the counts are at most ~2.8e14
  // control points (65537^3), so the byte totals cannot overflow 64 bits.
  Layout layout{std::uint64_t(solid.controlCount()), in.u32("negative-set count"), solid.channels,
                (flags & kFlagRegions) != 0, (flags & kFlagDetail) != 0};
  if (!layout.regions && layout.negatives != 0) throw InputError(where, "negative sets in a solid without regions");
  if (layout.negatives > layout.controls || layout.negatives > std::uint64_t(INT32_MAX))
    throw InputError(where, "more negative sets (" + std::to_string(layout.negatives) + ") than control points (" +
                                std::to_string(layout.controls) + ")");
  const std::uint64_t expected = layout.totalBytes();
  if (bytes.size() < expected)
    throw InputError(where, "truncated: " + std::to_string(bytes.size()) + " bytes, the header describes " +
                                std::to_string(expected));
  if (bytes.size() > expected)
    throw InputError(where, std::to_string(bytes.size() - expected) + " trailing bytes after the gradient solid");
  const std::string_view body(bytes.data(), bytes.size() - 4);
  Reader crc(std::string_view(bytes).substr(body.size()), where);
  if (crc.u32("CRC-32") != crcOf(body)) throw InputError(where, "CRC-32 mismatch: the file is corrupted");

  if (layout.regions) readMask(in, where, layout, solid.negativeIndex);
  readArray(in, where, "positive sets", layout.controls, solid.channels, false, solid.positive);
  if (layout.regions) {
    readArray(in, where, "distance", layout.controls, 1, false, solid.distance);
    readArray(in, where, "negative sets", layout.negatives, solid.channels, false, solid.negative);
  }
  if (layout.detail) readArray(in, where, "detail sigma", layout.controls, solid.channels, true, solid.detail);
  TS_CHECK(in.at() == body.size());
  solid.checkConsistent();
  return solid;
}

GradientSolid readGradientSolid(const std::string& path) {
  return decodeGradientSolid(readFileBytes(path), path);
}

void writeGradientSolid(const std::string& path, const GradientSolid& solid) {
  writeFileAtomically(path, encodeGradientSolid(solid));
}

std::uint64_t gradientSolidFileBytes(const GradientSolid& solid) {
  return layoutOf(solid).totalBytes();
}

std::uint64_t rawVolumeBytes(const GradientSolid& solid) {
  return std::uint64_t(solid.voxels.x()) * std::uint64_t(solid.voxels.y()) * std::uint64_t(solid.voxels.z()) *
         std::uint64_t(solid.channels);
}

}  // namespace texsynth
