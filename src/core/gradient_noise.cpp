#include "texsynth/core/gradient_noise.h"

#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

void validateFbm(const FbmOptions& options) {
  if (options.octaves < 1) throw ParameterError("octaves", "must be >= 1, got " + std::to_string(options.octaves));
  if (!(options.lacunarity > 0.0f) || !std::isfinite(options.lacunarity))
    throw ParameterError("lacunarity", "must be a finite number > 0");
  if (!(options.gain > 0.0f) || !std::isfinite(options.gain))
    throw ParameterError("gain", "must be a finite number > 0");
}

// Sums octaves of `octave(frequency, octaveSeed)`, normalized by the total amplitude.
template <class Octave>
float fractalSum(std::uint64_t seed, const FbmOptions& options, Octave octave) {
  validateFbm(options);
  float sum = 0, totalAmplitude = 0, amplitude = 1, frequency = 1;
  for (int k = 0; k < options.octaves; ++k) {
    sum += amplitude * octave(frequency, hashKey(seed, std::uint64_t(k), 0, 0x0f0b));
    totalAmplitude += amplitude;
    amplitude *= options.gain;
    frequency *= options.lacunarity;
  }
  return sum / totalAmplitude;
}

}  // namespace

float fbm2(float x, float y, std::uint64_t seed, const FbmOptions& options) {
  return fractalSum(seed, options, [&](float f, std::uint64_t s) { return gradientNoise2(x * f, y * f, s); });
}

float fbm3(float x, float y, float z, std::uint64_t seed, const FbmOptions& options) {
  return fractalSum(seed, options, [&](float f, std::uint64_t s) { return gradientNoise3(x * f, y * f, z * f, s); });
}

}  // namespace texsynth
