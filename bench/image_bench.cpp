// 2D random-access synthesis throughput: output pixels per second at 1024x1024 on 2 threads.
#include <benchmark/benchmark.h>

#include "test_support.h"
#include "texsynth/core/parallel.h"
#include "texsynth/image/tile_blend.h"
#include "texsynth/image/tile_deform.h"

namespace texsynth {
namespace {

constexpr int kSide = 1024;

// Synthesizes 1024x1024 windows of a texture built from a 128x128 exemplar on 2 threads.
template <class Texture, class Options>
void benchmarkWindows(benchmark::State& state) {
  ThreadLimit limit(2);
  Image exemplar = test::makeTestPattern(128, 128);
  Texture texture(exemplar, Options{});
  for (auto _ : state) benchmark::DoNotOptimize(texture.synthesizeWindow(0, 0, kSide, kSide).pixels.data());
  state.SetItemsProcessed(state.iterations() * kSide * kSide);
}

void BM_TileDeform(benchmark::State& state) {
  benchmarkWindows<TileDeformTexture, TileDeformOptions>(state);
}
BENCHMARK(BM_TileDeform)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TileBlend(benchmark::State& state) {
  benchmarkWindows<TileBlendTexture, TileBlendOptions>(state);
}
BENCHMARK(BM_TileBlend)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace texsynth
BENCHMARK_MAIN();
