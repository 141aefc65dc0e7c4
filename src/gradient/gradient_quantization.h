#pragma once
// The 8-bit quantization of a .tsgs file (docs/gradient-solids.md, "The .tsgs file"), shared by the
// file codec and quantizeGradientSolid so both give bit-identical values.
//
// An array holds sets of 4 * channels floats: the values of every channel, then d/du, d/dv, d/dw.
// Each channel has its own value range [lo, hi] (8-bit linear) and gradient bound g (8-bit with
// square-root companding over 255 levels centred on zero, so a zero slope stays exactly zero).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace texsynth::gradient_quantization {

struct ChannelRange {
  float lo = 0, hi = 0;  // values
  float g = 0;           // largest |gradient|
};

// Code 255 is never written for a gradient: 0..254 with 127 meaning zero.
inline constexpr int kGradientZero = 127;
inline constexpr int kGradientMaxCode = 254;

// The ranges of `sets` (count sets of 4 * channels floats); with `nonNegative` values below 0 are
// stored as 0 (a standard deviation). Throws ParameterError if a value is not finite.
std::vector<ChannelRange> measure(const float* sets, std::size_t count, int channels, bool nonNegative);

std::uint8_t encodeValue(float v, const ChannelRange& range);
float decodeValue(std::uint8_t code, const ChannelRange& range);
std::uint8_t encodeGradient(float x, const ChannelRange& range);
float decodeGradient(std::uint8_t code, const ChannelRange& range);

// Codes for / floats from a whole array, set by set, in memory order.
void encodeSets(const float* sets, std::size_t count, int channels, const std::vector<ChannelRange>& ranges,
                std::uint8_t* codes);
void decodeSets(const std::uint8_t* codes, std::size_t count, int channels, const std::vector<ChannelRange>& ranges,
                float* sets);

}  // namespace texsynth::gradient_quantization
