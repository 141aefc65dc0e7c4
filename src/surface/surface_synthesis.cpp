// Surface synthesis driver: coarse to fine over the mesh hierarchy, the discrete solver at every
// level and neighborhood size, sources upsampled between levels.
#include "texsynth/surface/surface_synthesis.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/core/timing.h"
#include "texsynth/image/discrete_steps.h"
#include "texsynth/surface/surface_domain.h"

namespace texsynth {
namespace {

using detail::ExemplarWindow;

void validate(std::span<const ExemplarAnalysis> analyses, const PreparedSurface& surface,
              const TextureOptimizationOptions& options) {
  if (options.solver != OptimizationSolver::Discrete)
    throw ParameterError("solver", "surface synthesis needs the discrete solver (least squares keeps no sources)");
  if (options.neighborhoodSizes != surface.neighborhoodSizes)
    throw ParameterError("neighborhood", "sizes differ from the ones the surface was prepared for");
  if (surface.levels.size() != surface.hierarchy.levels.size() || surface.levels.empty())
    throw ParameterError("surface", "is not prepared (prepareSurface)");
  const std::vector<AnalysisOptions> wanted = optimizationAnalysisOptions(options);
  if (analyses.size() != wanted.size())
    throw ParameterError(
        "analyses", "expected " + std::to_string(wanted.size()) + " analyses, got " + std::to_string(analyses.size()));
  for (std::size_t i = 0; i < analyses.size(); ++i) {
    const ExemplarAnalysis& a = analyses[i];
    if (a.levelCount() != int(surface.levels.size()) || a.neighborhoodSize != wanted[i].neighborhoodSize ||
        a.similarCount < wanted[i].similarCount || a.width != analyses[0].width || a.height != analyses[0].height)
      throw ParameterError("analyses", "analysis " + std::to_string(i) + " does not match the options (" +
                                           std::to_string(surface.levels.size()) +
                                           " levels as the mesh hierarchy, N, k, one exemplar)");
  }
}

// The coarsest level's start: random coherent patches. Every vertex copies the exemplar around
// a random pixel of its nearest active centre (of the first neighborhood size), at its flattened
// offset from that centre: pieces of exemplar structure about a stride across, where random
// pixels make the first matches pick the exemplar's flattest regions (as in 2D).
std::vector<std::int32_t> startSources(const SurfaceNeighborhoods& neighborhoods, const ExemplarWindow& window,
                                       std::uint64_t seed, int level) {
  auto randomPixel = [&](std::uint64_t element) {
    const std::uint64_t key = hashKey(seed, element, std::uint64_t(level), 0x57a7);
    const auto x = std::int32_t(uniformBelow(key, std::uint32_t(window.exemplarWidth)));
    const auto y = std::int32_t(uniformBelow(mix64(key), std::uint32_t(window.exemplarHeight)));
    return y * window.exemplarWidth + x;
  };
  std::vector<std::int32_t> sources(neighborhoods.vertexCount());
  parallelForChunks(0, std::int64_t(sources.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      const CoveringEntry* nearest = nullptr;
      for (const CoveringEntry& entry : neighborhoods.coveringOf(std::size_t(v)))
        if (!nearest ||
            entry.dx * entry.dx + entry.dy * entry.dy < nearest->dx * nearest->dx + nearest->dy * nearest->dy)
          nearest = &entry;
      sources[std::size_t(v)] =
          nearest
              ? window.shifted(randomPixel(std::uint64_t(neighborhoods.centres[std::size_t(nearest->neighborhood)])),
                               nearest->dx, nearest->dy)
              : randomPixel(std::uint64_t(v) | (1ull << 40));
    }
  });
  return sources;
}

// A finer level's start: each vertex continues the source of the nearest corner u of its parent
// triangle, moved by its offset from u in u's tangent frame (fine cells, h of the fine level),
// as 2D upsampling moves a child by its offset in the parent's block.
std::vector<std::int32_t> upsampleSources(const MeshLevel& coarse, const PreparedSurfaceLevel& coarsePrepared,
                                          const MeshLevel& fine, std::span<const std::int32_t> coarseSources,
                                          const ExemplarWindow& fineWindow) {
  std::vector<std::int32_t> sources(fine.mesh.vertexCount());
  const float perCell = 1.0f / fine.spacing;
  parallelForChunks(0, std::int64_t(sources.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      const Vec3i& triangle = coarse.mesh.triangles[std::size_t(fine.parentTriangle[std::size_t(v)])];
      const Vec3f& weights = fine.parentBarycentric[std::size_t(v)];
      int corner = 0;
      for (int k = 1; k < 3; ++k)
        if (weights[k] > weights[corner]) corner = k;
      const int u = triangle[corner];
      const Vec3f& t = coarsePrepared.tangents[std::size_t(u)];
      const Vec3f b = coarse.mesh.normals[std::size_t(u)].cross(t);
      const Vec3f d = fine.mesh.positions[std::size_t(v)] - coarse.mesh.positions[std::size_t(u)];
      sources[std::size_t(v)] =
          fineWindow.shifted(coarseSources[std::size_t(u)], d.dot(t) * perCell, -d.dot(b) * perCell);
    }
  });
  return sources;
}

}  // namespace

SurfaceSynthesisResult synthesizeSurface(std::span<const ExemplarAnalysis> analyses, const PreparedSurface& surface,
                                         const TextureOptimizationOptions& options, Progress& progress) {
  validate(analyses, surface, options);
  const auto start = std::chrono::steady_clock::now();
  const ExemplarAnalysis& base = analyses.back();
  const int levels = int(surface.levels.size());
  const int largest = *std::max_element(options.neighborhoodSizes.begin(), options.neighborhoodSizes.end());
  SurfaceSynthesisResult result;
  // As in 2D: start at the first level whose largest neighborhood fits inside the exemplar.
  int first = 0;
  while (first + 1 < levels && !ExemplarWindow(base, first, largest).bounded) ++first;
  result.firstLevel = first;

  const int steps = int(options.neighborhoodSizes.size()) * (options.maxIterations + 1);
  std::vector<std::int32_t> sources;
  for (int level = first; level < levels; ++level) {
    const MeshLevel& mesh = surface.hierarchy.levels[std::size_t(level)];
    const PreparedSurfaceLevel& prepared = surface.levels[std::size_t(level)];
    progress.begin("surface level " + std::to_string(level + 1) + "/" + std::to_string(levels) + " (" +
                       std::to_string(mesh.mesh.vertexCount()) + " vertices)",
                   steps);
    const ExemplarWindow window(base, level, options.neighborhoodSizes[0]);
    if (level == first)
      sources = startSources(prepared.neighborhoods[0], window, options.seed, level);
    else
      sources = upsampleSources(surface.hierarchy.levels[std::size_t(level - 1)],
                                surface.levels[std::size_t(level - 1)], mesh, sources, window);
    for (std::size_t scale = 0; scale < options.neighborhoodSizes.size(); ++scale) {
      const detail::SurfaceDomain domain{prepared.neighborhoods[scale], base.channels()};
      detail::optimizeDiscreteScale(domain, analyses, level, scale, options, sources, result.history, progress);
    }
    progress.end();
  }
  result.colors = colorsOfSources(base.levels.back().image, sources);
  result.sources = std::move(sources);
  result.seconds = secondsSince(start);
  return result;
}

std::vector<Vec3f> colorsOfSources(const Image& image, std::span<const std::int32_t> sources) {
  const std::int64_t pixels = std::int64_t(image.width) * image.height;
  std::vector<Vec3f> colors(sources.size());
  const int c = image.channels;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (sources[i] < 0 || sources[i] >= pixels)
      throw ParameterError("sources", "entry " + std::to_string(i) + " (" + std::to_string(sources[i]) +
                                          ") lies outside the " + std::to_string(image.width) + "x" +
                                          std::to_string(image.height) + " image");
    const float* p = image.pixels.data() + std::size_t(sources[i]) * c;
    colors[i] = c >= 3 ? Vec3f(p[0], p[1], p[2]) : Vec3f::Constant(p[0]);
  }
  return colors;
}

}  // namespace texsynth
