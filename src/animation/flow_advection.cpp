// Semi-Lagrangian transport of exemplar positions and colors, on image grids and mesh surfaces.
#include "texsynth/animation/flow_advection.h"

#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"

namespace texsynth {
namespace {

Vec2f velocityAt(const Image& velocities, float x, float y) {
  float v[4];
  velocities.sampleBilinearWrapped(double(x) + 0.5, double(y) + 0.5, v);
  return {v[0], v[1]};
}

}  // namespace

ExemplarPositions ExemplarPositions::atPixels(std::span<const std::int32_t> pixels, int exemplarWidth,
                                              int exemplarHeight) {
  return {exemplarWidth, exemplarHeight, std::vector<std::int32_t>(pixels.begin(), pixels.end()),
          std::vector<Vec2f>(pixels.size(), Vec2f::Zero())};
}

void ExemplarPositions::keepWhereUnchanged(std::span<const std::int32_t> after) {
  TS_CHECK(after.size() == pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i)
    if (pixels[i] != after[i]) pixels[i] = after[i], offsets[i] = Vec2f::Zero();
}

void ExemplarPositions::setMoved(std::size_t to, std::int32_t fromPixel, const Vec2f& fromOffset, const Vec2f& shift) {
  const Vec2f total = fromOffset + shift;
  const float sx = std::round(total.x()), sy = std::round(total.y());
  const int x = wrapIndex(std::int64_t(fromPixel % exemplarWidth) + std::int64_t(sx), exemplarWidth);
  const int y = wrapIndex(std::int64_t(fromPixel / exemplarWidth) + std::int64_t(sy), exemplarHeight);
  pixels[to] = std::int32_t(y) * exemplarWidth + x;
  offsets[to] = Vec2f(total.x() - sx, total.y() - sy);
}

std::vector<Vec2f> backtraceImage(const Image& velocities) {
  TS_CHECK(velocities.channels >= 2);
  const int width = velocities.width, height = velocities.height;
  std::vector<Vec2f> traced(std::size_t(width) * std::size_t(height));
  parallelForChunks(0, height, 8, [&](std::int64_t begin, std::int64_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < width; ++x) {
        const float* v = velocities.pixel(x, y);
        traced[std::size_t(y) * width + x] = -velocityAt(velocities, float(x) - 0.5f * v[0], float(y) - 0.5f * v[1]);
      }
  });
  return traced;
}

ExemplarPositions advectImagePositions(const ExemplarPositions& previous, std::span<const Vec2f> backtrace, int width) {
  TS_CHECK(previous.pixels.size() == backtrace.size() && width > 0 && backtrace.size() % std::size_t(width) == 0);
  const int height = int(backtrace.size() / std::size_t(width));
  ExemplarPositions next{previous.exemplarWidth, previous.exemplarHeight,
                         std::vector<std::int32_t>(previous.pixels.size()), std::vector<Vec2f>(previous.pixels.size())};
  parallelForChunks(0, height, 8, [&](std::int64_t begin, std::int64_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t i = std::size_t(y) * width + x;
        const Vec2f& d = backtrace[i];
        auto at = [&](float ox, float oy) {
          return std::size_t(wrapIndex(std::int64_t(y) + std::int64_t(oy), height)) * width +
                 std::size_t(wrapIndex(std::int64_t(x) + std::int64_t(ox), width));
        };
        // The pixel nearest the point, then one step further if its own offset puts its content
        // nearer the neighbour: motion goes into which pixel is copied, not into the exemplar
        // position, so a patch moves whole with its content (its edges too).
        float rx = std::round(d.x()), ry = std::round(d.y());
        const Vec2f rest = previous.offsets[at(rx, ry)] + Vec2f(d.x() - rx, d.y() - ry);
        rx += std::round(rest.x()), ry += std::round(rest.y());
        next.setMoved(i, previous.pixels[at(rx, ry)], previous.offsets[at(rx, ry)], Vec2f(d.x() - rx, d.y() - ry));
      }
  });
  return next;
}

double meanColorChange(const Image& a, const Image& b) {
  TS_CHECK(a.width == b.width && a.height == b.height);
  const int channels = std::min(a.channels, b.channels);
  double sum = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < channels; ++c) sum += std::abs(double(a.pixel(x, y)[c]) - b.pixel(x, y)[c]);
  const double count = double(a.width) * a.height * channels;
  return count > 0 ? 255.0 * sum / count : 0.0;
}

std::vector<SurfaceBacktrace> backtraceSurface(const Mesh& mesh, const SurfaceProjector& projector,
                                               std::span<const Vec3f> velocities) {
  TS_CHECK(velocities.size() == mesh.positions.size());
  std::vector<SurfaceBacktrace> traced(velocities.size());
  parallelForChunks(0, std::int64_t(traced.size()), 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      const SurfacePoint point = projector.closestPoint(mesh.positions[std::size_t(v)] - velocities[std::size_t(v)]);
      SurfaceBacktrace& t = traced[std::size_t(v)];
      t.triangle = point.triangle, t.barycentric = point.barycentric, t.position = point.position;
      int corner = 0;
      for (int k = 1; k < 3; ++k)
        if (point.barycentric[k] > point.barycentric[corner]) corner = k;
      t.nearestVertex = mesh.triangles[std::size_t(point.triangle)][corner];
    }
  });
  return traced;
}

ExemplarPositions advectSurfacePositions(const ExemplarPositions& previous, const Mesh& mesh,
                                         std::span<const Vec3f> tangents, float spacing,
                                         std::span<const SurfaceBacktrace> backtrace) {
  TS_CHECK(previous.pixels.size() == mesh.positions.size() && backtrace.size() == mesh.positions.size());
  ExemplarPositions next{previous.exemplarWidth, previous.exemplarHeight,
                         std::vector<std::int32_t>(previous.pixels.size()), std::vector<Vec2f>(previous.pixels.size())};
  const float perPixel = 1.0f / spacing;
  parallelForChunks(0, std::int64_t(next.pixels.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      const SurfaceBacktrace& t = backtrace[std::size_t(v)];
      // The point's offset from corner u in u's tangent frame, in exemplar pixels (exemplar x
      // along the tangent, exemplar y, down, against the bitangent).
      auto shiftFrom = [&](std::size_t u) {
        const Vec3f& tangent = tangents[u];
        const Vec3f d = t.position - mesh.positions[u];
        return Vec2f(d.dot(tangent) * perPixel, -d.dot(mesh.normals[u].cross(tangent)) * perPixel);
      };
      // Of the triangle's corners, the one whose content lies nearest the point (its own offset
      // counted): motion goes into which vertex is copied rather than into the exemplar position,
      // so a patch moves whole with its content.
      std::size_t best = std::size_t(t.nearestVertex);
      float bestLength = (previous.offsets[best] + shiftFrom(best)).squaredNorm();
      for (int k = 0; k < 3; ++k) {
        const auto u = std::size_t(mesh.triangles[std::size_t(t.triangle)][k]);
        const float length = (previous.offsets[u] + shiftFrom(u)).squaredNorm();
        if (length < bestLength) best = u, bestLength = length;
      }
      next.setMoved(std::size_t(v), previous.pixels[best], previous.offsets[best], shiftFrom(best));
    }
  });
  return next;
}

double meanColorChange(std::span<const Vec3f> a, std::span<const Vec3f> b) {
  TS_CHECK(a.size() == b.size());
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += double((a[i] - b[i]).cwiseAbs().sum());
  return a.empty() ? 0.0 : 255.0 * sum / (3.0 * double(a.size()));
}

}  // namespace texsynth
