// Candidate triples: validation, the triple arithmetic of eq. 4 and
// candidate slabs. The search and crossbarError are in candidate_triples_search.cpp.
#include "texsynth/exemplar/candidate_triples.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/wrap.h"

namespace texsynth {
namespace {

constexpr int kMaxNeighborhoodSize = 63;

std::string sizeText(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" + std::to_string(image.channels);
}

}  // namespace

const CoordinateTriple* CandidateTriples::at(Plane plane, std::int32_t pixel) const {
  TS_CHECK(pixel >= 0 && pixel < pixelCount());
  return triples[int(plane)].data() + std::size_t(pixel) * count;
}

const float* CandidateTriples::errorsAt(Plane plane, std::int32_t pixel) const {
  TS_CHECK(pixel >= 0 && pixel < pixelCount());
  return errors[int(plane)].data() + std::size_t(pixel) * count;
}

void validateCandidateTripleInputs(const Image& xy, const Image& yz, const Image& zx, int spacing,
                                   const CandidateTripleOptions& options) {
  if (xy.empty()) throw ParameterError("xy", "empty exemplar");
  if (std::int64_t(xy.width) * xy.height > std::numeric_limits<std::int32_t>::max())
    throw ParameterError("xy", "exemplar too large for 32-bit pixel indices");
  const Image* others[2] = {&yz, &zx};
  const char* names[2] = {"yz", "zx"};
  for (int i = 0; i < 2; ++i)
    if (others[i]->width != xy.width || others[i]->height != xy.height || others[i]->channels != xy.channels)
      throw ParameterError(names[i], "exemplar is " + sizeText(*others[i]) + " but xy is " + sizeText(xy) +
                                         " (all three planes must match)");
  if (spacing < 1) throw ParameterError("spacing", "must be at least 1, got " + std::to_string(spacing));
  if (options.count < 1) throw ParameterError("count", "must be at least 1, got " + std::to_string(options.count));
  const int n = options.neighborhoodSize;
  if (n < 1 || n % 2 == 0 || n > kMaxNeighborhoodSize)
    throw ParameterError("neighborhoodSize", "must be odd and in [1, " + std::to_string(kMaxNeighborhoodSize) +
                                                 "], got " + std::to_string(n));
  if (options.searchWidth < 1)
    throw ParameterError("searchWidth", "must be at least 1, got " + std::to_string(options.searchWidth));
  if (options.refineTriples < 0)
    throw ParameterError("refineTriples", "must be at least 0, got " + std::to_string(options.refineTriples));
  if (!(options.consistencyFactor >= 1.0f))
    throw ParameterError("consistencyFactor", "must be at least 1, got " + std::to_string(options.consistencyFactor));
  const std::int64_t width = std::min<std::int64_t>(options.searchWidth, xy.pixelCount());
  if (width * width < options.count)
    throw ParameterError("count", std::to_string(options.count) + " triples per pixel, but only " +
                                      std::to_string(width * width) + " pairs are searched");
}

std::int32_t offsetPixel(std::int32_t pixel, int width, int height, int du, int dv) {
  const int u = pixel % width, v = pixel / width;
  return std::int32_t(wrapIndex(std::int64_t(v) + dv, height) * width + wrapIndex(std::int64_t(u) + du, width));
}

CoordinateTriple offsetTriple(const CoordinateTriple& triple, int width, int height, int dx, int dy, int dz) {
  return {offsetPixel(triple.xy, width, height, dx, dy), offsetPixel(triple.yz, width, height, dy, dz),
          offsetPixel(triple.zx, width, height, dz, dx)};
}

CoordinateTriple slabTriple(const CandidateTriples& triples, Plane plane, std::int32_t pixel, int t, int spacing) {
  if (pixel < 0 || pixel >= triples.pixelCount())
    throw ParameterError("pixel", std::to_string(pixel) + " is outside the exemplar");
  if (std::abs(t) > triples.neighborhoodSize / 2)
    throw ParameterError(
        "t", "slab offset " + std::to_string(t) + " exceeds N/2 = " + std::to_string(triples.neighborhoodSize / 2));
  if (spacing < 1) throw ParameterError("spacing", "must be at least 1, got " + std::to_string(spacing));
  const CoordinateTriple first = triples.at(plane, pixel)[0];
  const int d = t * spacing;
  switch (plane) {
    case Plane::XY:
      return offsetTriple(first, triples.width, triples.height, 0, 0, d);
    case Plane::YZ:
      return offsetTriple(first, triples.width, triples.height, d, 0, 0);
    case Plane::ZX:
      return offsetTriple(first, triples.width, triples.height, 0, d, 0);
  }
  throw ParameterError("plane", "unknown plane");
}

}  // namespace texsynth
