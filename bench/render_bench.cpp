// Renderer timings: an ~80K-triangle mesh (the CGAL bunny, or a UV sphere of similar size
// when the data is not installed) at the default 768 x 768 with 2 x 2 supersampling.
#include <benchmark/benchmark.h>

#include "texsynth/core/data_paths.h"
#include "texsynth/core/parallel.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"
#include "texsynth/render/render_mesh.h"
#include "texsynth/render/slice_montage.h"

using namespace texsynth;

namespace {

const Mesh& benchMesh() {
  static const Mesh mesh = [] {
    if (auto path = cgalMesh("bunny00.off")) return readMesh(*path);
    return makeUvSphereMesh(Vec3f::Zero(), 1, 200, 200);
  }();
  return mesh;
}

void BM_RenderPerVertex(benchmark::State& state) {
  ThreadLimit limit(int(state.range(0)));
  const Mesh& mesh = benchMesh();
  for (auto _ : state) benchmark::DoNotOptimize(renderMesh(mesh).pixels.data());
  state.counters["triangles"] = double(mesh.triangleCount());
}
BENCHMARK(BM_RenderPerVertex)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RenderColorFunction(benchmark::State& state) {
  ThreadLimit limit(int(state.range(0)));
  const Mesh& mesh = benchMesh();
  SurfaceColorFunction checker = [](const std::vector<Vec3f>& points, const std::vector<Vec3f>&,
                                    std::vector<Vec3f>& colors) {
    colors.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      colors[i] =
          ((points[i] * 8).array().floor().cast<int>().sum() & 1) ? Vec3f(0.9f, 0.5f, 0.2f) : Vec3f(0.2f, 0.4f, 0.8f);
  };
  for (auto _ : state) benchmark::DoNotOptimize(renderMesh(mesh, checker).pixels.data());
}
BENCHMARK(BM_RenderColorFunction)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SliceMontage(benchmark::State& state) {
  const Volume volume(128, 128, 128, 3, 0.5f);
  for (auto _ : state) benchmark::DoNotOptimize(sliceMontage(volume).pixels.data());
}
BENCHMARK(BM_SliceMontage)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
