#include "texsynth/surface/surface_bake.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/geometry/surface_projector.h"

namespace texsynth {
namespace {

struct TexelHit {
  int triangle = -1;  // of the UV mesh; -1: no chart covers the texel
  Vec3f barycentric = Vec3f::Zero();
};

// Which UV-mesh triangle covers each texel centre, and where. Serial over triangles, so the
// later of two overlapping triangles wins whatever the thread count.
std::vector<TexelHit> rasterizeCharts(const Mesh& mesh, const std::vector<float>& uv, int size) {
  std::vector<TexelHit> hits(std::size_t(size) * size);
  auto texelPoint = [&](int v) {  // texel units, row 0 at v = 1
    return Vec2f(uv[2 * std::size_t(v)] * float(size), (1.0f - uv[2 * std::size_t(v) + 1]) * float(size));
  };
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vec3i& tri = mesh.triangles[t];
    const Vec2f a = texelPoint(tri[0]), b = texelPoint(tri[1]), c = texelPoint(tri[2]);
    const float area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (!(std::fabs(area) > 1e-12f)) continue;  // degenerate in UV space (or not finite)
    const float minX = std::min({a.x(), b.x(), c.x()}), maxX = std::max({a.x(), b.x(), c.x()});
    const float minY = std::min({a.y(), b.y(), c.y()}), maxY = std::max({a.y(), b.y(), c.y()});
    const int x0 = std::max(0, int(std::floor(minX))), x1 = std::min(size - 1, int(std::ceil(maxX)));
    const int y0 = std::max(0, int(std::floor(minY))), y1 = std::min(size - 1, int(std::ceil(maxY)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Vec2f p(float(x) + 0.5f, float(y) + 0.5f);
        // Barycentric weights by signed sub-areas; either winding of the chart counts.
        const float wa = ((b - p).x() * (c - p).y() - (b - p).y() * (c - p).x()) / area;
        const float wb = ((c - p).x() * (a - p).y() - (c - p).y() * (a - p).x()) / area;
        const float wc = 1.0f - wa - wb;
        if (wa < 0 || wb < 0 || wc < 0) continue;
        hits[std::size_t(y) * size + x] = {int(t), Vec3f(wa, wb, wc)};
      }
  }
  return hits;
}

// Grows the filled texels by `passes` rings: each empty texel next to filled ones gets their mean.
void dilate(Image& image, std::vector<unsigned char>& filled, int passes) {
  const int w = image.width, h = image.height;
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<unsigned char> next = filled;
    parallelFor(0, h, [&](std::int64_t row) {
      const int y = int(row);
      for (int x = 0; x < w; ++x) {
        if (filled[std::size_t(y) * w + x]) continue;
        Vec3f sum = Vec3f::Zero();
        int count = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h || !filled[std::size_t(ny) * w + nx]) continue;
            for (int c = 0; c < 3; ++c) sum[c] += image.at(nx, ny, c);
            ++count;
          }
        if (count == 0) continue;
        for (int c = 0; c < 3; ++c) image.at(x, y, c) = sum[c] / float(count);
        next[std::size_t(y) * w + x] = 1;
      }
    });
    filled.swap(next);
  }
}

}  // namespace

Image bakeVertexColors(const Mesh& uvMesh, const Mesh& colored, const SurfaceBakeOptions& options, Progress& progress) {
  if (options.size < 1 || options.size > 16384)
    throw ParameterError("size", "must be in [1, 16384], not " + std::to_string(options.size));
  if (options.dilation < -1 || options.dilation > 4096)
    throw ParameterError("dilation", "must be in [-1, 4096], not " + std::to_string(options.dilation));
  auto uv = uvMesh.attributes.find(kUvAttribute);
  if (uv == uvMesh.attributes.end() || uv->second.components != 2 ||
      uv->second.values.size() != 2 * uvMesh.vertexCount())
    throw ParameterError("uv", "the mesh has no texture coordinates");
  if (colored.colors.size() != colored.vertexCount() || colored.colors.empty())
    throw ParameterError("colors", "the colored mesh has no vertex colors");
  const int size = options.size;
  const std::vector<TexelHit> hits = rasterizeCharts(uvMesh, uv->second.values, size);
  const SurfaceProjector projector(colored);

  Image image(size, size, 3, 0.0f);
  std::vector<unsigned char> filled(hits.size(), 0);
  progress.begin("baking", size);
  // Read and written per row only: a row's texels see no other row, so threads never race.
  parallelFor(0, size, [&](std::int64_t row) {
    const int y = int(row);
    for (int x = 0; x < size; ++x) {
      const TexelHit& hit = hits[std::size_t(y) * size + x];
      if (hit.triangle < 0) continue;
      const Vec3i& tri = uvMesh.triangles[std::size_t(hit.triangle)];
      Vec3f point = Vec3f::Zero();
      for (int k = 0; k < 3; ++k) point += hit.barycentric[k] * uvMesh.positions[std::size_t(tri[k])];
      const SurfacePoint nearest = projector.closestPoint(point);
      const Vec3i& source = colored.triangles[std::size_t(nearest.triangle)];
      Vec3f color = Vec3f::Zero();
      for (int k = 0; k < 3; ++k) color += nearest.barycentric[k] * colored.colors[std::size_t(source[k])];
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = color[c];
      filled[std::size_t(y) * size + x] = 1;
    }
    progress.advance(1);
  });
  progress.end();

  const int passes = options.dilation >= 0 ? options.dilation : std::max(2, size / 256);
  dilate(image, filled, passes);
  // The rest gets the mean color in a fixed order (double sums row by row, then over rows).
  std::vector<Eigen::Vector3d> rowSums(std::size_t(size), Eigen::Vector3d::Zero());
  std::vector<std::int64_t> rowCounts(std::size_t(size), 0);
  parallelFor(0, size, [&](std::int64_t y) {
    for (int x = 0; x < size; ++x)
      if (filled[std::size_t(y) * size + x]) {
        for (int c = 0; c < 3; ++c) rowSums[std::size_t(y)][c] += image.at(x, int(y), c);
        ++rowCounts[std::size_t(y)];
      }
  });
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::int64_t count = 0;
  for (int y = 0; y < size; ++y) sum += rowSums[std::size_t(y)], count += rowCounts[std::size_t(y)];
  const Vec3f mean = count > 0 ? Vec3f((sum / double(count)).cast<float>()) : Vec3f::Constant(0.5f);
  for (std::size_t i = 0; i < filled.size(); ++i)
    if (!filled[i])
      for (int c = 0; c < 3; ++c) image.pixels[3 * i + std::size_t(c)] = mean[c];
  return image;
}

}  // namespace texsynth
