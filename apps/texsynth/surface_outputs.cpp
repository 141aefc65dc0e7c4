// The files `texsynth surface` writes: colored meshes, the coordinates file, a render, a baked texture.
#include <chrono>

#include "cli_common.h"
#include "surface_args.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/render_mesh.h"
#include "texsynth/surface/surface_bake.h"
#include "texsynth/surface/surface_coordinates.h"

namespace texsynth::cli {

namespace {

RenderOptions renderOptions(const SurfaceArgs& args) {
  RenderOptions options;
  options.width = options.height = args.renderSize;
  return options;
}

// Views evenly around the model's up, each from 20 degrees above.
std::vector<std::pair<float, float>> renderAngles(int views) {
  std::vector<std::pair<float, float>> angles;
  for (int v = 0; v < views; ++v) angles.push_back({30.0f + 360.0f * float(v) / float(views), 20.0f});
  return angles;
}

}  // namespace

void requireSurfaceOutputMemory(const SurfaceArgs& args) {
  if (!args.render.empty())
    requireMemory(renderMemoryBytes(renderOptions(args), args.views), "--render-size", "the rendered views");
  // Per texel: the chart hit (16 bytes), the float image (12), the fill masks (2), the encoder's copy (8).
  if (!args.bake.empty())
    requireMemory(double(args.bakeSize) * args.bakeSize * 40.0, "--bake-size",
                  "a " + std::to_string(args.bakeSize) + "x" + std::to_string(args.bakeSize) + " texture");
}

nlohmann::json writeSurfaceOutputs(const SurfaceArgs& args, const SurfaceResult& result, Progress& progress) {
  nlohmann::json written = nlohmann::json::array();
  auto clock = std::chrono::steady_clock::now();
  auto done = [&](const std::string& file) {
    const auto now = std::chrono::steady_clock::now();
    written.push_back({{"file", file}, {"seconds", std::chrono::duration<double>(now - clock).count()}});
    clock = now;
  };
  const std::size_t files = args.outputs.size() + (args.coords.empty() ? 0 : 1) + (args.render.empty() ? 0 : 1);
  progress.begin("writing outputs", std::int64_t(files));
  for (const std::string& out : args.outputs) {
    writeMesh(out, result.colored);
    done(out);
    progress.advance(1);
  }
  if (!args.coords.empty()) {
    Mesh coords = result.colored;
    storeSourceCoordinates(coords, result.sources, result.exemplarWidth, result.exemplarHeight);
    writeMesh(args.coords, coords);
    done(args.coords);
    progress.advance(1);
  }
  if (!args.render.empty()) {
    RenderOptions options = renderOptions(args);
    options.up = viewUp(args.up, result.colored);
    writeImage(args.render, renderViews(result.colored, nullptr, renderAngles(args.views), options));
    done(args.render);
    progress.advance(1);
  }
  progress.end();
  if (!args.bake.empty()) {  // its own stage: the one output that takes a while
    SurfaceBakeOptions options;
    options.size = args.bakeSize;
    writeImage(args.bake, bakeVertexColors(*result.uvMesh, result.colored, options, progress));
    done(args.bake);
  }
  return written;
}

}  // namespace texsynth::cli
