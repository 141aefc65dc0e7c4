#include "texsynth/render/render_mesh.h"

#include <cmath>

#include "camera.h"
#include "rasterizer.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {

using render_detail::Camera;
using render_detail::ScreenVertex;
using render_detail::VisibilityBuffer;

namespace {

// Items (vertices, visible samples) per chunk of parallel work: fixed, so the split never
// depends on the thread count.
constexpr std::int64_t kChunk = 16384;

// Everything the shading passes need: camera, projected vertices, visibility, and the list
// of visible samples in raster order.
struct Scene {
  const Mesh& mesh;
  const RenderOptions& options;
  std::vector<Vec3f> vertexNormals;  // empty for flat shading
  Camera camera;
  std::vector<ScreenVertex> screen;
  VisibilityBuffer visibility;
  std::vector<std::int64_t> rowStart;  // visible samples before each sample row; size height + 1
  std::vector<std::int64_t> visible;   // sample index (y * width + x) of each visible sample
  Vec3f lightWorld;
};

std::vector<Vec3f> smoothNormals(const Mesh& mesh) {
  if (mesh.normals.size() == mesh.positions.size()) return mesh.normals;
  Mesh geometry;
  geometry.positions = mesh.positions;
  geometry.triangles = mesh.triangles;
  geometry.computeNormals();
  return std::move(geometry.normals);
}

void gatherVisibleSamples(Scene& scene) {
  const VisibilityBuffer& vis = scene.visibility;
  std::vector<std::int64_t> counts(std::size_t(vis.height) + 1, 0);
  parallelFor(0, vis.height, [&](std::int64_t y) {
    std::int64_t n = 0;
    for (int x = 0; x < vis.width; ++x) n += vis.at(x, int(y)) >= 0;
    counts[y + 1] = n;
  });
  for (int y = 0; y < vis.height; ++y) counts[y + 1] += counts[y];
  scene.visible.resize(std::size_t(counts.back()));
  parallelFor(0, vis.height, [&](std::int64_t y) {
    std::int64_t k = counts[y];
    for (int x = 0; x < vis.width; ++x)
      if (vis.at(x, int(y)) >= 0) scene.visible[k++] = y * vis.width + x;
  });
  scene.rowStart = std::move(counts);
}

Scene prepareScene(const Mesh& mesh, const RenderOptions& options) {
  validateRenderOptions(options);
  mesh.validate("mesh");
  Scene scene{mesh, options, {}, {}, {}, {}, {}, {}, {}};
  const int sampleWidth = options.width * options.supersample, sampleHeight = options.height * options.supersample;
  if (options.smoothShading) scene.vertexNormals = smoothNormals(mesh);
  scene.camera = render_detail::fitCamera(mesh, options, sampleWidth, sampleHeight);
  scene.lightWorld = scene.camera.viewToWorldDirection(options.lightDirection.normalized());
  scene.screen.resize(mesh.positions.size());
  parallelForChunks(0, std::int64_t(mesh.positions.size()), kChunk, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i)
      scene.screen[i] = render_detail::snapToGrid(scene.camera.project(mesh.positions[i]));
  });
  scene.visibility = render_detail::rasterize(scene.screen, mesh.triangles, sampleWidth, sampleHeight);
  gatherVisibleSamples(scene);
  return scene;
}

// The surface under one visible sample: perspective-correct barycentric weights, the world
// point, and a unit normal.
struct SurfaceSample {
  std::int32_t triangle;
  Vec3f weights, point, normal;
};

SurfaceSample surfaceAt(const Scene& scene, std::int64_t sample) {
  const int width = scene.visibility.width;
  const int x = int(sample % width), y = int(sample / width);
  SurfaceSample s;
  s.triangle = scene.visibility.triangle[sample];
  const Vec3i& t = scene.mesh.triangles[s.triangle];
  const ScreenVertex &a = scene.screen[t[0]], &b = scene.screen[t[1]], &c = scene.screen[t[2]];
  Vec3f screenWeights = render_detail::screenBarycentrics(a, b, c, x, y);
  // Perspective correction: attributes are affine in screen space only after dividing by depth.
  Vec3f weighted(screenWeights[0] * a.inverseDepth, screenWeights[1] * b.inverseDepth,
                 screenWeights[2] * c.inverseDepth);
  s.weights = weighted / weighted.sum();
  const auto& p = scene.mesh.positions;
  s.point = s.weights[0] * p[t[0]] + s.weights[1] * p[t[1]] + s.weights[2] * p[t[2]];
  Vec3f normal = Vec3f::Zero();
  if (!scene.vertexNormals.empty()) {
    const auto& n = scene.vertexNormals;
    normal = s.weights[0] * n[t[0]] + s.weights[1] * n[t[1]] + s.weights[2] * n[t[2]];
  }
  // Flat shading, or vertex normals that cancel out: fall back to the face normal, and for a
  // face that is degenerate in space (but not on screen) to the direction towards the eye.
  if (!(normal.squaredNorm() > 1e-20f) || !normal.allFinite()) normal = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
  if (!(normal.squaredNorm() > 1e-30f) || !normal.allFinite()) normal = scene.camera.eye - s.point;
  s.normal = normal.normalized();
  return s;
}

Vec3f shade(const Scene& scene, const Vec3f& color, const Vec3f& normal) {
  const float ambient = scene.options.ambient;
  return color * (ambient + (1.0f - ambient) * std::abs(normal.dot(scene.lightWorld)));
}

// Box-filters shaded visible samples (and background) down to the output image.
Image resolve(const Scene& scene, const std::vector<Vec3f>& shaded) {
  const RenderOptions& options = scene.options;
  const int s = options.supersample;
  const float inverseCount = 1.0f / float(s * s);
  Image image(options.width, options.height, 3);
  parallelFor(0, options.height, [&](std::int64_t py) {
    // One cursor per sample row into the raster-ordered visible list.
    std::vector<std::int64_t> cursor(s);
    for (int j = 0; j < s; ++j) cursor[j] = scene.rowStart[py * s + j];
    for (int px = 0; px < options.width; ++px) {
      Vec3f sum = Vec3f::Zero();
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i)
          sum += scene.visibility.at(px * s + i, int(py) * s + j) >= 0 ? shaded[cursor[j]++] : options.background;
      float* out = image.pixel(px, int(py));
      for (int c = 0; c < 3; ++c) out[c] = sum[c] * inverseCount;
    }
  });
  return image;
}

}  // namespace

Image renderMesh(const Mesh& mesh, const RenderOptions& options) {
  Scene scene = prepareScene(mesh, options);
  std::vector<Vec3f> shaded(scene.visible.size());
  parallelForChunks(0, std::int64_t(shaded.size()), kChunk, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t k = begin; k < end; ++k) {
      SurfaceSample s = surfaceAt(scene, scene.visible[k]);
      Vec3f color = options.defaultColor;
      if (!mesh.colors.empty()) {
        const Vec3i& t = mesh.triangles[s.triangle];
        color = s.weights[0] * mesh.colors[t[0]] + s.weights[1] * mesh.colors[t[1]] + s.weights[2] * mesh.colors[t[2]];
      }
      shaded[k] = shade(scene, color, s.normal);
    }
  });
  return resolve(scene, shaded);
}

Image renderMesh(const Mesh& mesh, const SurfaceColorFunction& colorAt, const RenderOptions& options) {
  if (!colorAt) throw ParameterError("colorAt", "is empty");
  Scene scene = prepareScene(mesh, options);
  const std::size_t count = scene.visible.size();
  std::vector<Vec3f> points(count), normals(count), colors;
  parallelForChunks(0, std::int64_t(count), kChunk, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t k = begin; k < end; ++k) {
      SurfaceSample s = surfaceAt(scene, scene.visible[k]);
      points[k] = s.point;
      normals[k] = s.normal;
    }
  });
  colorAt(points, normals, colors);
  if (colors.size() != count)
    throw ParameterError(
        "colorAt", "returned " + std::to_string(colors.size()) + " colours for " + std::to_string(count) + " points");
  parallelForChunks(0, std::int64_t(count), kChunk, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t k = begin; k < end; ++k) colors[k] = shade(scene, colors[k], normals[k]);
  });
  return resolve(scene, colors);
}

double renderMemoryBytes(const RenderOptions& options, int views) {
  const double samples = double(options.width) * options.supersample * double(options.height) * options.supersample;
  return double(std::max(views, 1)) * (16.0 * samples + 2 * 12.0 * double(options.width) * options.height);
}

Image renderViews(const Mesh& mesh, const SurfaceColorFunction* colorAt,
                  const std::vector<std::pair<float, float>>& yawPitch, const RenderOptions& options) {
  if (yawPitch.empty()) throw ParameterError("yawPitch", "needs at least one view");
  validateRenderOptions(options);
  if (std::int64_t(options.width) * std::int64_t(yawPitch.size()) > 65536)
    throw ParameterError("yawPitch", "too many views: the montage would be wider than 65536 pixels");
  std::vector<Image> views;
  for (const auto& [yaw, pitch] : yawPitch) {
    RenderOptions view = options;
    view.yawDegrees = yaw;
    view.pitchDegrees = pitch;
    views.push_back(colorAt ? renderMesh(mesh, *colorAt, view) : renderMesh(mesh, view));
  }
  return sideBySide(views);
}

Image sideBySide(const std::vector<Image>& images, int gap) {
  if (images.empty()) throw ParameterError("images", "nothing to place side by side");
  if (gap < 0) throw ParameterError("gap", "must be >= 0");
  int width = gap, height = 0;
  for (const Image& image : images) {
    if (image.channels != 3) throw ParameterError("images", "side by side needs RGB images");
    width += image.width + gap, height = std::max(height, image.height);
  }
  Image montage(width, height + 2 * gap, 3, 1.0f);
  int x = gap;
  for (const Image& image : images) {
    for (int y = 0; y < image.height; ++y)
      std::copy_n(image.pixel(0, y), std::size_t(image.width) * 3, montage.pixel(x, y + gap));
    x += image.width + gap;
  }
  return montage;
}

}  // namespace texsynth
