// Surface texture quality (surface_quality.h): vertex patches resampled on the mesh and matched
// exactly against the exemplar's patches by eval's PatchIndex, as `texsynth eval` does on images;
// flatness and completeness in surface_patch_statistics.cpp.
#include "texsynth/surface/surface_quality.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <vector>

#include "surface_patch_statistics.h"
#include "texsynth/core/error.h"
#include "texsynth/core/random.h"
#include "texsynth/core/timing.h"
#include "texsynth/eval/histogram_distance.h"
#include "texsynth/eval/patch_index.h"
#include "texsynth/geometry/mesh_topology.h"
#include "texsynth/surface/surface_neighborhoods.h"

namespace texsynth {
namespace {

constexpr int kTransforms = 8;  // rotations by 0, 90, 180, 270 degrees, each plain and mirrored
// Evaluated vertices per nearest-patch batch (bounds the query memory for samples = 0).
constexpr std::size_t kBatch = 4096;

void validate(const Image& exemplar, const Mesh& mesh, std::span<const Vec3f> tangents,
              const SurfaceQualityOptions& options) {
  if (options.patchSize < 3 || options.patchSize % 2 == 0)
    throw ParameterError("patchSize", "must be odd and at least 3, got " + std::to_string(options.patchSize));
  if (options.samples < 0)
    throw ParameterError("samples", "must be >= 0 (0 = every vertex), got " + std::to_string(options.samples));
  if (exemplar.empty()) throw ParameterError("exemplar", "is empty");
  if (exemplar.width < options.patchSize || exemplar.height < options.patchSize)
    throw ParameterError("exemplar", "is " + std::to_string(exemplar.width) + "x" + std::to_string(exemplar.height) +
                                         ", smaller than the " + std::to_string(options.patchSize) + "x" +
                                         std::to_string(options.patchSize) + " patch");
  if (mesh.colors.empty()) throw InputError("mesh", "has no vertex colors to evaluate");
  if (mesh.colors.size() != mesh.vertexCount())
    throw InputError("mesh", "has " + std::to_string(mesh.colors.size()) + " vertex colors for " +
                                 std::to_string(mesh.vertexCount()) + " vertices");
  for (const Vec3f& c : mesh.colors)
    if (!c.allFinite()) throw InputError("mesh", "has non-finite vertex colors");
  if (tangents.size() != mesh.vertexCount())
    throw ParameterError("tangents", "has " + std::to_string(tangents.size()) + " entries for " +
                                         std::to_string(mesh.vertexCount()) + " vertices");
  for (const Vec3f& t : tangents)
    if (!t.allFinite()) throw ParameterError("tangents", "contains non-finite values");
}

// The exemplar as RGB on 0..255.
Image exemplarRgb255(const Image& exemplar) {
  Image rgb = exemplar.withChannels(3);
  for (float& value : rgb.pixels) {
    if (!std::isfinite(value)) throw ParameterError("exemplar", "contains non-finite values (NaN or infinity)");
    value *= 255.0f;
  }
  return rgb;
}

// Per vertex: its distance along mesh edges to the nearest border vertex, computed only up to
// `limit` (larger distances, and meshes without borders, give infinity).
std::vector<double> borderDistances(const Mesh& mesh, const MeshTopology& topology, double limit) {
  const int n = topology.vertexCount();
  std::vector<double> distance(std::size_t(n), std::numeric_limits<double>::infinity());
  if (topology.closed()) return distance;
  std::vector<std::vector<int>> adjacent(static_cast<std::size_t>(n));
  for (const Vec3i& t : topology.triangles())
    for (int e = 0; e < 3; ++e) {
      adjacent[std::size_t(t[e])].push_back(t[(e + 1) % 3]);
      adjacent[std::size_t(t[(e + 1) % 3])].push_back(t[e]);
    }
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (int v = 0; v < n; ++v)
    if (topology.isBorderVertex(v)) {
      distance[std::size_t(v)] = 0;
      queue.push({0.0, v});
    }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[std::size_t(v)]) continue;
    for (int w : adjacent[std::size_t(v)]) {
      const double next = d + double((mesh.positions[std::size_t(w)] - mesh.positions[std::size_t(v)]).norm());
      if (next < distance[std::size_t(w)] && next < limit) {
        distance[std::size_t(w)] = next;
        queue.push({next, w});
      }
    }
  }
  return distance;
}

// The cell of the untransformed patch that cell (x, y) of transform k reads (0 <= x, y < size).
int transformedCell(int k, int x, int y, int size) {
  const int last = size - 1;
  if (k & 4) std::swap(x, y);  // transpose: with the flips below, all 8 symmetries of the square
  if (k & 1) x = last - x;
  if (k & 2) y = last - y;
  return y * size + x;
}

}  // namespace

SurfaceQuality evaluateSurface(const Image& exemplar, const Mesh& coloredMesh, std::span<const Vec3f> tangents,
                               const SurfaceQualityOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  validate(exemplar, coloredMesh, tangents, options);
  const Image exemplar255 = exemplarRgb255(exemplar);
  Mesh mesh = coloredMesh;
  if (mesh.normals.size() != mesh.vertexCount()) mesh.computeNormals();
  const MeshTopology topology(mesh, "mesh");

  SurfaceQuality quality;
  quality.spacing = std::sqrt(mesh.surfaceArea() / double(mesh.vertexCount()));
  const int size = options.patchSize, radius = size / 2;

  // The evaluable vertices, then the sample: the first `samples` in hashed order, ascending.
  const double limit = 1.25 * (radius * std::sqrt(2.0) + 0.5) * quality.spacing;
  const std::vector<double> border =
      options.skipBorders ? borderDistances(mesh, topology, limit)
                          : std::vector<double>(mesh.vertexCount(), std::numeric_limits<double>::infinity());
  std::vector<std::int32_t> centres;
  for (int v = 0; v < topology.vertexCount(); ++v)
    if (topology.fanCount(v) > 0 && border[std::size_t(v)] >= limit) centres.push_back(v);
  quality.nearBorder = topology.vertexCount() - int(centres.size());
  if (centres.empty())
    throw InputError("mesh", "has no vertex whose " + std::to_string(size) + "x" + std::to_string(size) +
                                 " patch stays clear of a mesh border");
  if (options.samples > 0 && std::size_t(options.samples) < centres.size()) {
    auto key = [&](std::int32_t v) { return std::pair{hashKey(options.seed, std::uint64_t(v)), v}; };
    std::nth_element(centres.begin(), centres.begin() + options.samples, centres.end(),
                     [&](std::int32_t a, std::int32_t b) { return key(a) < key(b); });
    centres.resize(std::size_t(options.samples));
    std::sort(centres.begin(), centres.end());
  }
  quality.evaluated = int(centres.size());

  const SurfaceNeighborhoods patches =
      resampleNeighborhoods(mesh, topology, tangents, float(quality.spacing), size, centres);
  std::vector<float> colors(mesh.vertexCount() * 3);
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
    for (int c = 0; c < 3; ++c) colors[3 * v + std::size_t(c)] = mesh.colors[v][c] * 255.0f;

  // Per batch: the exact nearest patch of every plain patch, then of its 7 other symmetries,
  // each looked for only below the plain distance (which prunes most of their search); the
  // plain patches' deviations (flatness) and their exact nearest to the exemplar's (completeness).
  const PatchIndex index(exemplar255, size);
  const double flatThreshold = surface_detail::flatnessThreshold(exemplar255, size);
  surface_detail::CompletenessSearch completeness(exemplar255, size, options.seed);
  std::size_t flat = 0;
  const std::size_t values = std::size_t(size) * size * 3;
  std::vector<float> plain, turned;
  std::vector<double> limits;
  double plainSum = 0, invariantSum = 0;  // summed in vertex order
  for (std::size_t first = 0; first < centres.size(); first += kBatch) {
    const std::size_t count = std::min(kBatch, centres.size() - first);
    plain.resize(count * values);
    turned.resize(count * (kTransforms - 1) * values);
    for (std::size_t i = 0; i < count; ++i) {
      const std::span<float> patch(&plain[i * values], values);
      patches.resample(first + i, colors, 3, patch);
      if (surface_detail::rgbPatchDeviation(patch.data(), size * size) < flatThreshold) ++flat;
      for (int k = 1; k < kTransforms; ++k) {
        float* out = &turned[(i * (kTransforms - 1) + std::size_t(k - 1)) * values];
        for (int y = 0; y < size; ++y)
          for (int x = 0; x < size; ++x)
            std::copy_n(&patch[std::size_t(transformedCell(k, x, y, size)) * 3], 3, out + (y * size + x) * 3);
      }
    }
    const std::vector<PatchMatch> plainMatches = index.nearestVectors(plain, count);
    completeness.add(plain, count);
    limits.resize(count * (kTransforms - 1));
    for (std::size_t i = 0; i < limits.size(); ++i) limits[i] = plainMatches[i / (kTransforms - 1)].meanSquared;
    const std::vector<PatchMatch> turnedMatches = index.nearestVectors(turned, limits.size(), limits);
    for (std::size_t i = 0; i < count; ++i) {
      double best = plainMatches[i].meanSquared;
      plainSum += best;
      for (int k = 0; k < kTransforms - 1; ++k)
        best = std::min(best, turnedMatches[i * (kTransforms - 1) + std::size_t(k)].meanSquared);
      invariantSum += best;
    }
  }
  quality.coherence = std::sqrt(plainSum / double(centres.size()));
  quality.rotationInvariant = std::sqrt(invariantSum / double(centres.size()));
  quality.flatness = double(flat) / double(centres.size()) - 0.1;
  quality.completeness = completeness.result();

  Image vertexColors(int(mesh.vertexCount()), 1, 3);
  vertexColors.pixels = std::move(colors);
  quality.histogram = histogramDistance(vertexColors, exemplar255);
  quality.seconds = secondsSince(start);
  return quality;
}

}  // namespace texsynth
