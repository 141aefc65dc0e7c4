// Parallel k-coherence synthesis on a mesh level with continuous coordinates
// (surface_parallel.h).
#include "texsynth/surface/surface_parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "continuous_coordinates.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/core/wrap.h"
#include "texsynth/image/color_histogram_cost.h"
#include "texsynth/image/exemplar_usage.h"
#include "texsynth/image/exemplar_window.h"

namespace texsynth {
namespace {

using surface_detail::atPixel;
using surface_detail::NearestLookup;
using surface_detail::nearestPixel;
using surface_detail::stencilDistance;
using surface_detail::subPixel;
using surface_detail::wrapCoordinate;

// Members within this many cells of the vertex propose candidates (its 3 x 3 ring).
constexpr float kProposingRadius = 1.6f;

}  // namespace

std::vector<Vec2f> patchSurfaceCoordinates(const SurfaceNeighborhoods& neighborhoods, std::uint64_t seed, int level,
                                           int spacing, int exemplarWidth, int exemplarHeight) {
  auto randomPixel = [&](std::uint64_t element) {
    const std::uint64_t key = hashKey(seed, element, std::uint64_t(level), 0x57a7);
    return Vec2f(float(uniformBelow(key, std::uint32_t(exemplarWidth))),
                 float(uniformBelow(mix64(key), std::uint32_t(exemplarHeight))));
  };
  std::vector<Vec2f> coordinates(neighborhoods.vertexCount());
  const float h = float(spacing);
  parallelForChunks(0, std::int64_t(coordinates.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      const CoveringEntry* nearest = nullptr;
      for (const CoveringEntry& entry : neighborhoods.coveringOf(std::size_t(v)))
        if (!nearest ||
            entry.dx * entry.dx + entry.dy * entry.dy < nearest->dx * nearest->dx + nearest->dy * nearest->dy)
          nearest = &entry;
      if (!nearest) {
        coordinates[std::size_t(v)] = randomPixel(std::uint64_t(v) | (1ull << 40));
        continue;
      }
      const Vec2f c = randomPixel(std::uint64_t(neighborhoods.centres[std::size_t(nearest->neighborhood)]));
      coordinates[std::size_t(v)] = Vec2f(wrapCoordinate(c.x() + h * nearest->dx, exemplarWidth),
                                          wrapCoordinate(c.y() + h * nearest->dy, exemplarHeight));
    }
  });
  return coordinates;
}

std::vector<Vec2f> upsampleSurfaceCoordinates(const Mesh& coarseGeometry, std::span<const Vec3f> coarseTangents,
                                              const MeshLevel& fine, const Mesh& fineGeometry,
                                              std::span<const Vec2f> coarseCoordinates, float pixelsPerUnit,
                                              int exemplarWidth, int exemplarHeight) {
  std::vector<Vec2f> coordinates(fineGeometry.vertexCount());
  parallelForChunks(0, std::int64_t(coordinates.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      const Vec3i& triangle = coarseGeometry.triangles[std::size_t(fine.parentTriangle[std::size_t(v)])];
      const Vec3f& weights = fine.parentBarycentric[std::size_t(v)];
      int corner = 0;
      for (int k = 1; k < 3; ++k)
        if (weights[k] > weights[corner]) corner = k;
      const auto u = std::size_t(triangle[corner]);
      const Vec3f& t = coarseTangents[u];
      const Vec3f b = coarseGeometry.normals[u].cross(t);
      const Vec3f d = fineGeometry.positions[std::size_t(v)] - coarseGeometry.positions[u];
      const Vec2f& c = coarseCoordinates[u];
      coordinates[std::size_t(v)] = Vec2f(wrapCoordinate(c.x() + d.dot(t) * pixelsPerUnit, exemplarWidth),
                                          wrapCoordinate(c.y() - d.dot(b) * pixelsPerUnit, exemplarHeight));
    }
  });
  return coordinates;
}

void jitterSurfaceCoordinates(std::vector<Vec2f>& coordinates, int level, int spacing, float strength,
                              std::uint64_t seed, int exemplarWidth, int exemplarHeight) {
  if (strength <= 0) return;
  const float reach = float(spacing) * strength;
  for (std::size_t v = 0; v < coordinates.size(); ++v) {
    const std::uint64_t key = hashKey(seed, std::uint64_t(v), std::uint64_t(level), 0x71e4);
    const float jx = std::floor(reach * (2.0f * uniform01(key) - 1.0f) + 0.5f);
    const float jy = std::floor(reach * (2.0f * uniform01(mix64(key)) - 1.0f) + 0.5f);
    coordinates[v] = Vec2f(wrapCoordinate(coordinates[v].x() + jx, exemplarWidth),
                           wrapCoordinate(coordinates[v].y() + jy, exemplarHeight));
  }
}

std::vector<float> colorsAtCoordinates(const Image& image, std::span<const Vec2f> coordinates, int channels) {
  const int c = channels > 0 ? channels : image.channels;
  std::vector<float> colors(coordinates.size() * std::size_t(c));
  const NearestLookup lookup{image, c};
  parallelForChunks(0, std::int64_t(coordinates.size()), 8192, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
      std::copy_n(lookup(coordinates[std::size_t(v)].x(), coordinates[std::size_t(v)].y()), c,
                  colors.data() + std::size_t(v) * c);
  });
  return colors;
}

std::vector<std::int32_t> pixelsOfCoordinates(std::span<const Vec2f> coordinates, int exemplarWidth,
                                              int exemplarHeight) {
  std::vector<std::int32_t> pixels(coordinates.size());
  for (std::size_t v = 0; v < coordinates.size(); ++v)
    pixels[v] = nearestPixel(coordinates[v], exemplarWidth, exemplarHeight);
  return pixels;
}

std::vector<Vec2f> coordinatesOfPixels(std::span<const std::int32_t> pixels, int exemplarWidth) {
  std::vector<Vec2f> coordinates(pixels.size());
  for (std::size_t v = 0; v < pixels.size(); ++v) coordinates[v] = atPixel(pixels[v], exemplarWidth);
  return coordinates;
}

double correctSurfaceCoordinates(const SurfaceStencil& stencil, const ExemplarAnalysis& analysis, int level,
                                 const SurfaceParallelOptions& options, std::vector<Vec2f>& coordinates) {
  const ExemplarLevel& exemplar = analysis.levels[std::size_t(level)];
  const Image& image = exemplar.image;
  const int channels = image.channels, k = analysis.similarCount;
  const float h = float(exemplar.spacing);
  const int width = analysis.width, height = analysis.height;
  const auto vertices = std::int64_t(coordinates.size());
  const int subpasses = std::max(1, options.subpasses);
  std::vector<double> distances(coordinates.size(), 0.0);
  const NearestLookup lookup{image, channels};
  const detail::ExemplarWindow window(analysis, level, stencil.size, detail::PixelNorm::Euclidean);
  for (int subpass = 0; subpass < subpasses; ++subpass) {
    const std::vector<float> colors = colorsAtCoordinates(image, coordinates);
    // The usage and histogram terms in squared units, per stencil member: usageWeight * sigma^2 *
    // (usage - 1) and histogramWeight * sigma^2 * (share / exemplar share - 1).
    const std::vector<std::int32_t> sources = pixelsOfCoordinates(coordinates, width, height);
    const detail::UsageMap usage(window, sources, options.usageWeight > 0 ? 1.0f : 0.0f);
    const float sigma = detail::colorSpread(window);
    const bool histogramActive = options.histogramBand > 0 && options.histogramWeight > 0;
    const detail::ColorHistogramCost histogram =
        histogramActive ? detail::ColorHistogramCost(image, analysis.colorChannels, sources)
                        : detail::ColorHistogramCost();
    const float usageScale = options.usageWeight * sigma, histogramScale = options.histogramWeight * sigma * sigma;
    auto usageTerm = [&](const Vec2f& c, std::size_t members) {
      return options.usageWeight > 0 ? float(members) * usageScale * usage.cost(nearestPixel(c, width, height)) : 0.0f;
    };
    // The energies within the histogram band of `e` (infinity stays infinity).
    auto withinBand = [&](float e) { return e + options.histogramBand * std::abs(e); };
    std::vector<Vec2f> next = coordinates;
    parallelForChunks(0, vertices, 512, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::pair<float, Vec2f>> near;
      std::vector<Vec2f> candidates;
      std::vector<std::int32_t> seen;
      for (std::int64_t v = begin; v < end; ++v) {
        if (subpasses > 1 && int(hashKey(options.seed, std::uint64_t(v), std::uint64_t(level), 0x5b9a) %
                                 std::uint64_t(subpasses)) != subpass)
          continue;
        const std::span<const NeighborhoodMember> members = stencil.of(std::size_t(v));
        candidates.clear();
        seen.clear();
        auto propose = [&](const Vec2f& c) {
          const std::int32_t pixel = nearestPixel(c, width, height);
          if (std::find(seen.begin(), seen.end(), pixel) != seen.end()) return;
          seen.push_back(pixel);
          candidates.push_back(c);
          const std::int32_t* similar = analysis.similarAt(level, pixel);
          for (int i = 1; i < k; ++i) candidates.push_back(atPixel(similar[i], width, subPixel(c)));
        };
        for (const NeighborhoodMember& m : members)
          if (m.dx * m.dx + m.dy * m.dy <= kProposingRadius * kProposingRadius)
            propose(Vec2f(coordinates[std::size_t(m.vertex)].x() - h * m.dx,
                          coordinates[std::size_t(m.vertex)].y() - h * m.dy));
        // The energy: stencil distance plus usage term; the least wins, ties keep the earlier.
        float best = std::numeric_limits<float>::infinity(), least = best;
        Vec2f bestCoordinate = coordinates[std::size_t(v)];
        if (!histogram.active()) {
          for (const Vec2f& c : candidates) {
            const float sum = stencilDistance(lookup, colors.data(), members, c, h, usageTerm(c, members.size()), best);
            if (sum < best) best = sum, bestCoordinate = c;
          }
          least = best;
        } else {
          // Among the candidates within the band of the least energy, the least energy plus
          // histogram term: the histogram steers only between nearly equal matches.
          near.clear();
          for (const Vec2f& c : candidates) {
            const float bound = withinBand(best);
            const float sum =
                stencilDistance(lookup, colors.data(), members, c, h, usageTerm(c, members.size()), bound);
            if (sum < bound) near.push_back({sum, c});
            best = std::min(best, sum);
          }
          least = best;
          const float limit = withinBand(best);
          float chosen = std::numeric_limits<float>::infinity();
          for (const auto& [sum, c] : near) {
            if (sum > limit) continue;
            const float total =
                sum + float(members.size()) * histogramScale * histogram.cost(nearestPixel(c, width, height));
            if (total < chosen) chosen = total, best = sum, bestCoordinate = c;
          }
        }
        // A move the usage term pays for in full (negative energy: the reward of an under-used
        // region exceeds the color distance) is not taken where usage is held.
        if (options.holdUsagePaidMoves && least < 0) bestCoordinate = coordinates[std::size_t(v)];
        next[std::size_t(v)] =
            Vec2f(wrapCoordinate(bestCoordinate.x(), width), wrapCoordinate(bestCoordinate.y(), height));
        distances[std::size_t(v)] = double(best) / double(members.size() * std::size_t(channels));
      }
    });
    coordinates = std::move(next);
  }
  double sum = 0;
  for (double d : distances) sum += d;
  return vertices > 0 ? sum / double(vertices) : 0.0;
}

std::vector<float> stencilDistances(const SurfaceStencil& stencil, const ExemplarAnalysis& analysis, int level,
                                    std::span<const Vec2f> coordinates) {
  return stencilDistances(stencil, analysis.levels[std::size_t(level)], coordinates);
}

std::vector<float> stencilDistances(const SurfaceStencil& stencil, const ExemplarLevel& exemplar,
                                    std::span<const Vec2f> coordinates) {
  const int channels = exemplar.image.channels;
  const float h = float(exemplar.spacing);
  const NearestLookup lookup{exemplar.image, channels};
  const std::vector<float> colors = colorsAtCoordinates(exemplar.image, coordinates);
  std::vector<float> distances(coordinates.size());
  parallelForChunks(0, std::int64_t(coordinates.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      const std::span<const NeighborhoodMember> members = stencil.of(std::size_t(v));
      const float sum = stencilDistance(lookup, colors.data(), members, coordinates[std::size_t(v)], h);
      distances[std::size_t(v)] = sum / float(members.size() * std::size_t(channels));
    }
  });
  return distances;
}

}  // namespace texsynth
