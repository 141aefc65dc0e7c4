// Coordinate upsampling and jitter of parallel synthesis (Lefebvre & Hoppe 2005, sections
// 3.2 and 3.3), on absolute pixel positions so that any window is reproducible.
#include <cmath>

#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/core/wrap.h"
#include "texsynth/image/parallel_synthesis.h"
#include "texsynth/image/window_support.h"

namespace texsynth {
namespace {

// Floor division and non-negative modulo for negative absolute positions.
int floorDiv2(int v) {
  return v >= 0 ? v / 2 : -((1 - v) / 2);
}
}  // namespace

SourceCoordinates tilingCoordinates(int x0, int y0, int width, int height, int spacing, int exemplarWidth,
                                    int exemplarHeight) {
  SourceCoordinates out(x0, y0, width, height);
  for (int y = y0; y < y0 + height; ++y)
    for (int x = x0; x < x0 + width; ++x) {
      out.at(x, y)[0] = wrapIndex(std::int64_t(x) * spacing, exemplarWidth);
      out.at(x, y)[1] = wrapIndex(std::int64_t(y) * spacing, exemplarHeight);
    }
  return out;
}

SourceCoordinates randomCoordinates(int x0, int y0, int width, int height, std::uint64_t seed, int level,
                                    int exemplarWidth, int exemplarHeight) {
  SourceCoordinates out(x0, y0, width, height);
  for (int y = y0; y < y0 + height; ++y)
    for (int x = x0; x < x0 + width; ++x) {
      const std::uint64_t key = hashKey(seed, latticeId(x, y), std::uint64_t(level), 0x57a7);
      out.at(x, y)[0] = std::int32_t(uniformBelow(key, std::uint32_t(exemplarWidth)));
      out.at(x, y)[1] = std::int32_t(uniformBelow(mix64(key), std::uint32_t(exemplarHeight)));
    }
  return out;
}

SourceCoordinates upsampleCoordinates(const SourceCoordinates& parent, const SourceCoordinates& region, int spacing,
                                      int exemplarWidth, int exemplarHeight) {
  SourceCoordinates out(region.x0, region.y0, region.width, region.height);
  TS_CHECK(floorDiv2(out.x0) >= parent.x0 && floorDiv2(out.y0) >= parent.y0);
  TS_CHECK(floorDiv2(out.x0 + out.width - 1) < parent.x0 + parent.width);
  TS_CHECK(floorDiv2(out.y0 + out.height - 1) < parent.y0 + parent.height);
  // floor(h * (delta - 1/2)) for delta = 0 and 1: children h apart, centred on the parent.
  const int offset[2] = {int(std::floor(-0.5 * spacing)), int(std::floor(0.5 * spacing))};
  parallelForChunks(0, out.height, kRowChunk, [&](std::int64_t begin, std::int64_t end) {
    for (int j = int(begin); j < int(end); ++j) {
      const int y = out.y0 + j, py = floorDiv2(y);
      for (int x = out.x0; x < out.x0 + out.width; ++x) {
        const int px = floorDiv2(x);
        const std::int32_t* source = parent.at(px, py);
        std::int32_t* target = out.at(x, y);
        target[0] = wrapIndex(std::int64_t(source[0]) + offset[x - 2 * px], exemplarWidth);
        target[1] = wrapIndex(std::int64_t(source[1]) + offset[y - 2 * py], exemplarHeight);
      }
    }
  });
  return out;
}

void jitterCoordinates(SourceCoordinates& coords, int level, int spacing, float strength, std::uint64_t seed,
                       int exemplarWidth, int exemplarHeight) {
  if (strength == 0.0f) return;
  const double amplitude = double(spacing) * strength;
  parallelForChunks(0, coords.height, kRowChunk, [&](std::int64_t begin, std::int64_t end) {
    for (int j = int(begin); j < int(end); ++j) {
      const int y = coords.y0 + j;
      for (int x = coords.x0; x < coords.x0 + coords.width; ++x) {
        const std::uint64_t id = latticeId(x, y);
        // xi in [-1, 1): one independent hash per axis (the pass argument).
        const double xiX = 2.0 * uniform01(hashKey(seed, id, std::uint64_t(level), 0)) - 1.0;
        const double xiY = 2.0 * uniform01(hashKey(seed, id, std::uint64_t(level), 1)) - 1.0;
        std::int32_t* target = coords.at(x, y);
        target[0] = wrapIndex(std::int64_t(target[0]) + std::int64_t(std::floor(amplitude * xiX + 0.5)), exemplarWidth);
        target[1] =
            wrapIndex(std::int64_t(target[1]) + std::int64_t(std::floor(amplitude * xiY + 0.5)), exemplarHeight);
      }
    }
  });
}

}  // namespace texsynth
