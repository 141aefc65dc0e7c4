// Quality-metric kernels: exact patch nearest neighbours and the whole evaluateImage.
// Images: an exemplar cropped from a larger synthetic texture (tests' kind of pattern, with a
// noise channel, so a hard case for the search), and an output twice its side cut from the same
// texture, so that output patches have close but rarely exact matches, as good synthesis does.
#include <benchmark/benchmark.h>

#include <cmath>

#include "texsynth/core/random.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/eval/patch_index.h"

namespace texsynth {
namespace {

// A texture like tests/support's makeTestPattern, on 0..1.
Image texture(int width, int height, std::uint64_t seed) {
  Image image(width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float noise = uniform01(hashKey(seed, latticeId(x / 3, y / 3)));
      float waves = 0.5f + 0.25f * std::sin(0.35f * x + 0.8f * std::sin(0.21f * y));
      image.at(x, y, 0) = 0.6f * waves + 0.4f * noise;
      image.at(x, y, 1) = 0.5f + 0.5f * std::sin(0.17f * (x + 2 * y));
      image.at(x, y, 2) = noise;
    }
  return image;
}

Image window(const Image& image, int x0, int y0, int w, int h) {
  Image out(w, h, image.channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < image.channels; ++c) out.at(x, y, c) = image.at(x0 + x, y0 + y, c);
  return out;
}

// Args: exemplar side; the output is twice that.
void BM_EvaluateImage(benchmark::State& state) {
  const int side = int(state.range(0));
  Image source = texture(3 * side, 3 * side, 5);
  Image exemplar = window(source, 0, 0, side, side);
  Image output = window(source, side / 2, side / 3, 2 * side, 2 * side);
  for (auto _ : state) benchmark::DoNotOptimize(evaluateImage(exemplar, output));
  state.SetLabel(std::to_string(side) + "^2 exemplar vs " + std::to_string(2 * side) + "^2 output");
}
BENCHMARK(BM_EvaluateImage)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();

// Exact nearest exemplar patch of every output patch (the coherence half), 0..255 values.
void BM_PatchIndexNearest(benchmark::State& state) {
  const int side = int(state.range(0));
  Image source = texture(3 * side, 3 * side, 7);
  for (float& v : source.pixels) v *= 255;
  PatchIndex index(window(source, 0, 0, side, side), 7);
  Image output = window(source, side / 2, side / 3, 2 * side, 2 * side);
  for (auto _ : state) benchmark::DoNotOptimize(index.nearest(output));
  state.SetItemsProcessed(state.iterations() * std::int64_t(output.width - 6) * (output.height - 6));
}
BENCHMARK(BM_PatchIndexNearest)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();

// Far queries (noise against a texture): the search's worst case, close to brute force.
void BM_PatchIndexNearestNoise(benchmark::State& state) {
  const int side = int(state.range(0));
  Image exemplar = texture(side, side, 3);
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
