// Quality-metric kernels: exact patch nearest neighbours and the whole evaluateImage.
// Images: an exemplar cropped from a larger synthetic texture (tests' kind of pattern, with a
// noise channel, so a hard case for the search), and an output twice its side cut from the same
// texture, so that output patches have close but rarely exact matches, as good synthesis does.
#include <benchmark/benchmark.h>

#include <cmath>

#include "test_support.h"
#include "texsynth/core/random.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/eval/patch_index.h"

namespace texsynth {
namespace {

// Args: exemplar side; the output is twice that.
void BM_EvaluateImage(benchmark::State& state) {
  const int side = int(state.range(0));
  Image source = test::makeTestPattern(3 * side, 3 * side, 5);
  Image exemplar = source.crop(0, 0, side, side);
  Image output = source.crop(side / 2, side / 3, 2 * side, 2 * side);
  for (auto _ : state) benchmark::DoNotOptimize(evaluateImage(exemplar, output));
  state.SetLabel(std::to_string(side) + "^2 exemplar vs " + std::to_string(2 * side) + "^2 output");
}
BENCHMARK(BM_EvaluateImage)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();

// Exact nearest exemplar patch of every output patch (the coherence half), 0..255 values.
void BM_PatchIndexNearest(benchmark::State& state) {
  const int side = int(state.range(0));
  Image source = test::makeTestPattern(3 * side, 3 * side, 7);
  for (float& v : source.pixels) v *= 255;
  PatchIndex index(source.crop(0, 0, side, side), 7);
  Image output = source.crop(side / 2, side / 3, 2 * side, 2 * side);
  for (auto _ : state) benchmark::DoNotOptimize(index.nearest(output));
  state.SetItemsProcessed(state.iterations() * std::int64_t(output.width - 6) * (output.height - 6));
}
BENCHMARK(BM_PatchIndexNearest)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();

// Far queries (noise against a texture): the search's worst case, close to brute force.
void BM_PatchIndexNearestNoise(benchmark::State& state) {
  const int side = int(state.range(0));
  Image exemplar = test::makeTestPattern(side, side, 3);
  Image noise(2 * side, 2 * side, 3);
  for (std::size_t i = 0; i < noise.pixels.size(); ++i) noise.pixels[i] = 255 * uniform01(hashKey(9, i));
  for (float& v : exemplar.pixels) v *= 255;
  PatchIndex index(exemplar, 7);
  for (auto _ : state) benchmark::DoNotOptimize(index.nearest(noise));
  state.SetItemsProcessed(state.iterations() * std::int64_t(noise.width - 6) * (noise.height - 6));
}
BENCHMARK(BM_PatchIndexNearestNoise)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace texsynth

BENCHMARK_MAIN();
