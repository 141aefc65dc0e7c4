#include "demo_fallbacks.h"

#include <cmath>

#include "texsynth/core/random.h"

namespace texsynth::cli {

// Smooth value noise on a lattice with period `period` (so the texture tiles).
static float valueNoise(float x, float y, int period, std::uint64_t seed) {
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float tx = x - x0, ty = y - y0;
  tx = tx * tx * (3 - 2 * tx), ty = ty * ty * (3 - 2 * ty);
  auto corner = [&](int i, int j) {
    int wi = ((x0 + i) % period + period) % period, wj = ((y0 + j) % period + period) % period;
    return uniform01(hashKey(seed, latticeId(wi, wj)));
  };
  float top = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * tx;
  float bottom = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * tx;
  return top + (bottom - top) * ty;
}

Image proceduralMarble(int size, std::uint64_t seed) {
  Image image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float turbulence = 0, amplitude = 1;
      for (int octave = 0; octave < 5; ++octave) {
        int period = 4 << octave;
        float scale = float(period) / size;
        turbulence += amplitude * std::abs(valueNoise(x * scale, y * scale, period, seed + octave) - 0.5f);
        amplitude *= 0.5f;
      }
      float vein = 0.5f + 0.5f * std::sin(2.0f * float(M_PI) * (2.0f * x / size + 3.0f * turbulence));
      float v = std::pow(vein, 0.6f);
      image.at(x, y, 0) = 0.35f + 0.6f * v;
      image.at(x, y, 1) = 0.33f + 0.55f * v;
      image.at(x, y, 2) = 0.30f + 0.5f * v;
    }
  return image;
}

}  // namespace texsynth::cli
