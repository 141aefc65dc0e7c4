// Solid-texture timings: evaluation throughput (points/s, reported as items/s) for each
// method on 2 threads, and the time to colour the vertices of an ~80K-face mesh (the CGAL
// bunny, or a UV sphere of similar size when the data is not installed).
#include <benchmark/benchmark.h>

#include <string>

#include "test_support.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"
#include "texsynth/solid/lazy_blocks.h"
#include "texsynth/solid/lazy_solid.h"
#include "texsynth/solid/solid_consumers.h"
#include "texsynth/solid/tile_blend_solid.h"
#include "texsynth/solid/tile_deform_solid.h"

using namespace texsynth;

namespace {

const Mesh& benchMesh() {
  static const Mesh mesh = [] {
    Mesh m =
        cgalMesh("bunny00.off") ? readMesh(*cgalMesh("bunny00.off")) : makeUvSphereMesh(Vec3f::Zero(), 1, 200, 200);
    if (m.normals.size() != m.positions.size()) m.computeNormals();
    return m;
  }();
  return mesh;
}

enum Method { kVolume, kStackZ, kStackAll, kTileBlend };

std::unique_ptr<SolidTexture> makeSolid(int method) {
  const Image exemplar = test::makeTestPattern(128, 128);
  const SolidPlacement placement = fitPlacement(benchMesh().bounds(), 128, 3.0f);
  TileDeformSolidOptions deform;
  deform.placement = placement;
  if (method == kTileBlend) {
    TileBlendSolidOptions blend;
    blend.placement = placement;
    return makeTileBlendSolid(exemplar, blend);
  }
  if (method == kVolume) {
    Volume volume(64, 64, 64, 3);
    for (std::size_t i = 0; i < volume.voxels.size(); ++i) volume.voxels[i] = uniform01(hashKey(1, i));
    return makeTileDeformSolid(volume, deform);
  }
  deform.stacking = method == kStackZ ? StackAxes::Z : StackAxes::All;
  return makeStackedTileDeformSolid(exemplar, deform);
}

const char* methodName(int method) {
  static const char* names[] = {"volume", "stack-z", "stack-xyz", "tile-blend"};
  return names[method];
}

// 2^20 points on a 128 x 128 x 64 grid over the mesh's box, in raster order (as slices,
// volumes and render rows ask), each with a random unit normal (all three planes used).
void BM_SolidEvaluate(benchmark::State& state) {
  ThreadLimit limit(2);
  auto solid = makeSolid(int(state.range(0)));
  const Box3f box = benchMesh().bounds();
  const int count = 1 << 20;
  std::vector<Vec3f> points(count), normals(count);
  for (int i = 0; i < count; ++i) {
    const Vec3f cell((i & 127) + 0.5f, ((i >> 7) & 127) + 0.5f, (i >> 14) + 0.5f);
    points[i] = box.min + cell.cwiseQuotient(Vec3f(128, 128, 64)).cwiseProduct(box.size());
    for (int a = 0; a < 3; ++a) normals[i][a] = uniform01(hashKey(3, i, a)) - 0.5f;
  }
  for (Vec3f& n : normals) n.normalize();
  std::vector<float> values(std::size_t(count) * solid->channels());
  for (auto _ : state) {
    solid->evaluate(points, normals, values);
    benchmark::DoNotOptimize(values.data());
  }
  state.SetItemsProcessed(state.iterations() * count);
  state.SetLabel(methodName(int(state.range(0))));
}
BENCHMARK(BM_SolidEvaluate)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ColorMeshVertices(benchmark::State& state) {
  ThreadLimit limit(2);
  auto solid = makeSolid(int(state.range(0)));
  Mesh mesh = benchMesh();
  for (auto _ : state) {
    colorMeshVertices(mesh, *solid);
    benchmark::DoNotOptimize(mesh.colors.data());
  }
  state.counters["faces"] = double(mesh.triangleCount());
  state.SetLabel(methodName(int(state.range(0))));
}
BENCHMARK(BM_ColorMeshVertices)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->UseRealTime();

// Lazy synthesis of a full R^3 volume (fresh cache each iteration) from a 64^2 test pattern on
// 2 threads; items/s = delivered voxels/s. range(1) = 1: paper defaults (L = 4, N = 7/9, 2 passes
// of 8 subpasses, 3 at the coarsest level); 0: a light setting (L = 3, N = 5, 1 pass of 8
// subpasses). range(2) = 1: dual-grid correction (M = 12) above the coarsest level; 0: the
// standard scheme, whose every level grows by about passes * 8 * (N/2 - 1/2) voxels on each side
// (a 16^3 box costs about as much as a 64^3 one).
void BM_LazySolidVolume(benchmark::State& state) {
  ThreadLimit limit(2);
  const int n = int(state.range(0));
  LazySolidOptions options;
  if (state.range(1) == 0) {
    options.levels = 3;
    options.neighborhoodSizes = {5};
    options.passes = 1;
    options.coarsestPasses = 1;
  }
  options.dualGrid = state.range(2) == 1;
  const Image exemplar = test::makeTestPattern(64, 64);
  std::vector<LazyLevelStats> stats;
  for (auto _ : state) {
    state.PauseTiming();
    LazySolid solid(exemplar, options);  // analysis and candidate triples: not timed
    state.ResumeTiming();
    solid.synthesizeBox({0, 0, 0}, {n, n, n});
    stats = solid.stats();
  }
  std::int64_t corrections = 0, voxels = 0;
  for (const LazyLevelStats& s : stats) corrections += s.corrections, voxels += s.voxelsSynthesized;
  state.counters["corrections"] = double(corrections);
  state.counters["voxels_all_levels"] = double(voxels);
  state.SetItemsProcessed(state.iterations() * std::int64_t(n) * n * n);
  state.SetLabel(std::string(state.range(1) ? "paper defaults" : "light") +
                 (state.range(2) ? ", dual grid" : ", standard scheme"));
}
BENCHMARK(BM_LazySolidVolume)
    ->Args({64, 0, 0})
    ->Args({16, 1, 0})
    ->Args({16, 1, 1})
    ->Args({64, 1, 0})
    ->Args({64, 1, 1})
    ->Args({128, 1, 1})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// How close a level's block plan comes to the exact dependent set its history windows give
// (lazy::windowDependencies), for one delivered 4^3 block at a finer level with the paper's
// defaults (N = 9, 2 passes of 8 subpasses, no field: window radius 4). range(0) = 1: dual-grid
// correction (M = 12); 0: the standard scheme. Counters: the exact voxels needed from upsampling,
// the voxels the plan synthesizes, and their ratio; the time is that of the exact computation.
void BM_LazyPlanVersusWindows(benchmark::State& state) {
  LazySolidOptions options;
  const bool grid = state.range(0) == 1;
  const int radius = 4;
  const lazy::LevelSchedule schedule = lazy::levelSchedule(options, 1, grid);
  std::vector<Vec3i> deliver;
  for (int slot = 0; slot < lazy::kBlockVoxels; ++slot) deliver.push_back({slot % 4, slot / 4 % 4, slot / 16});
  std::size_t exact = 0;
  for (auto _ : state) exact = lazy::windowDependencies(schedule, deliver, radius).front().size();
  std::vector<int> classes;
  for (const lazy::CorrectionStep& step : schedule.steps) classes.push_back(step.voxelClass);
  const std::vector<lazy::BlockKey> blocks = {lazy::blockKey(0, 0, 0)};
  const lazy::LazyDependencyPlan plan =
      grid ? lazy::planGridLevel(blocks, options.gridCellSize, radius, true) : lazy::planLevel(blocks, classes, radius);
  const double planned = double(plan.layers.front().size()) * lazy::kBlockVoxels;
  state.counters["exact_voxels"] = double(exact);
  state.counters["planned_voxels"] = planned;
  state.counters["planned_per_exact"] = planned / double(exact);
  state.SetLabel(grid ? "dual grid" : "standard scheme");
}
BENCHMARK(BM_LazyPlanVersusWindows)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
