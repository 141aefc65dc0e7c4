#include "gradient_quantization.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth::gradient_quantization {
namespace {

// The code among `rounded` and its two neighbours (within [0, maxCode]) whose decoded value is
// nearest to `x`: a decoded value then always encodes to itself, which makes quantizing idempotent
// even where float rounding would push the plain rounded code off by one.
template <typename Decode>
std::uint8_t nearestCode(float x, long rounded, long maxCode, Decode decode) {
  rounded = std::clamp(rounded, 0L, maxCode);
  long best = rounded;
  double bestError = std::abs(double(decode(std::uint8_t(rounded))) - x);
  for (long code : {rounded - 1, rounded + 1}) {
    if (code < 0 || code > maxCode) continue;
    const double error = std::abs(double(decode(std::uint8_t(code))) - x);
    if (error < bestError) best = code, bestError = error;
  }
  return std::uint8_t(best);
}

}  // namespace

std::vector<ChannelRange> measure(const float* sets, std::size_t count, int channels, bool nonNegative) {
  std::vector<ChannelRange> ranges(static_cast<std::size_t>(channels));
  const std::size_t setSize = 4 * std::size_t(channels);
  for (int c = 0; c < channels; ++c) {
    ChannelRange& range = ranges[std::size_t(c)];
    float lo = INFINITY, hi = -INFINITY, g = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const float* set = sets + i * setSize;
      for (int slot = 0; slot < 4; ++slot)
        if (!std::isfinite(set[slot * channels + c])) throw ParameterError("solid", "holds a non-finite value");
      lo = std::min(lo, set[c]), hi = std::max(hi, set[c]);
      for (int slot = 1; slot < 4; ++slot) g = std::max(g, std::abs(set[slot * channels + c]));
    }
    if (count == 0) lo = hi = 0;
    if (nonNegative) lo = std::max(lo, 0.0f), hi = std::max(hi, lo);
    range = {lo, hi, g};
  }
  return ranges;
}

float decodeValue(std::uint8_t code, const ChannelRange& range) {
  // Written as a blend so that code 0 gives lo and code 255 gives hi exactly.
  const double t = double(code) / 255.0;
  return float(double(range.lo) * (1.0 - t) + double(range.hi) * t);
}

std::uint8_t encodeValue(float v, const ChannelRange& range) {
  if (!(range.hi > range.lo)) return 0;
  const double t = (double(v) - range.lo) / (double(range.hi) - range.lo);
  return nearestCode(v, std::lround(t * 255.0), 255, [&](std::uint8_t code) { return decodeValue(code, range); });
}

float decodeGradient(std::uint8_t code, const ChannelRange& range) {
  // Square-root companding: the code is linear in sqrt(|x| / g), so steps are finest near zero.
  const double s = double(int(code) - kGradientZero) / kGradientZero;
  return float(s * std::abs(s) * double(range.g));
}

std::uint8_t encodeGradient(float x, const ChannelRange& range) {
  if (!(range.g > 0)) return kGradientZero;
  const double s = std::sqrt(std::abs(double(x)) / range.g) * kGradientZero;
  const long rounded = kGradientZero + (x < 0 ? -std::lround(s) : std::lround(s));
  return nearestCode(x, rounded, kGradientMaxCode, [&](std::uint8_t code) { return decodeGradient(code, range); });
}

void encodeSets(const float* sets, std::size_t count, int channels, const std::vector<ChannelRange>& ranges,
                std::uint8_t* codes) {
  const std::size_t setSize = 4 * std::size_t(channels);
  for (std::size_t i = 0; i < count * setSize; ++i) {
    const std::size_t slot = (i % setSize) / std::size_t(channels);
    const ChannelRange& range = ranges[i % std::size_t(channels)];
    codes[i] = slot == 0 ? encodeValue(sets[i], range) : encodeGradient(sets[i], range);
  }
}

void decodeSets(const std::uint8_t* codes, std::size_t count, int channels, const std::vector<ChannelRange>& ranges,
                float* sets) {
  const std::size_t setSize = 4 * std::size_t(channels);
  for (std::size_t i = 0; i < count * setSize; ++i) {
    const std::size_t slot = (i % setSize) / std::size_t(channels);
    const ChannelRange& range = ranges[i % std::size_t(channels)];
    sets[i] = slot == 0 ? decodeValue(codes[i], range) : decodeGradient(codes[i], range);
  }
}

}  // namespace texsynth::gradient_quantization
