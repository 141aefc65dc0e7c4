#include "gradient_baselines.h"

#include <zfp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth::bench {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Per output index along an axis: the input indices and weights it sums.
using Taps = std::vector<std::vector<std::pair<int, float>>>;

// Box filter from n to m samples: output j averages the inputs by their overlap with [j, j+1) n/m.
Taps boxTaps(int n, int m) {
  Taps taps(static_cast<std::size_t>(m));
  const double step = double(n) / m;
  for (int j = 0; j < m; ++j) {
    const double lo = j * step, hi = (j + 1) * step;
    for (int i = int(lo); i < n && i < hi; ++i) {
      const double overlap = std::min(hi, i + 1.0) - std::max(lo, double(i));
      if (overlap > 0) taps[std::size_t(j)].emplace_back(i, float(overlap / step));
    }
  }
  return taps;
}

// Catmull-Rom from m samples back to n, sample centres aligned ((x + 1/2) m/n - 1/2), edges clamped.
Taps catmullRomTaps(int m, int n) {
  Taps taps(static_cast<std::size_t>(n));
  for (int x = 0; x < n; ++x) {
    const double u = (x + 0.5) * m / n - 0.5;
    const int i = int(std::floor(u));
    const float t = float(u - i), t2 = t * t, t3 = t2 * t;
    const float w[4] = {0.5f * (-t3 + 2 * t2 - t), 0.5f * (3 * t3 - 5 * t2 + 2), 0.5f * (-3 * t3 + 4 * t2 + t),
                        0.5f * (t3 - t2)};
    for (int k = 0; k < 4; ++k) taps[std::size_t(x)].emplace_back(std::clamp(i - 1 + k, 0, m - 1), w[k]);
  }
  return taps;
}

// Filters `in` along `axis` (0 x, 1 y, 2 z) with `taps`; the axis's new size is taps.size().
Volume resampleAxis(const Volume& in, int axis, const Taps& taps) {
  int size[3] = {in.nx, in.ny, in.nz};
  size[axis] = int(taps.size());
  Volume out(size[0], size[1], size[2], in.channels);
  parallelFor(0, out.nz, [&](std::int64_t z) {
    for (int y = 0; y < out.ny; ++y)
      for (int x = 0; x < out.nx; ++x) {
        int at[3] = {x, y, int(z)};
        float* o = out.voxel(x, y, int(z));
        for (const auto& [index, weight] : taps[std::size_t(at[axis])]) {
          at[axis] = index;
          const float* v = in.voxel(at[0], at[1], at[2]);
          for (int c = 0; c < in.channels; ++c) o[c] += weight * v[c];
        }
      }
  });
  return out;
}

Volume firstChannels(const Volume& volume, int channels) {
  if (volume.channels == channels) return volume;
  Volume out(volume.nx, volume.ny, volume.nz, channels);
  for (std::size_t i = 0; i < volume.voxelCount(); ++i)
    for (int c = 0; c < channels; ++c) out.voxels[i * channels + c] = volume.voxels[i * volume.channels + c];
  return out;
}

}  // namespace

double volumeRms(const Volume& a, const Volume& b, int channels) {
  TS_CHECK(a.nx == b.nx && a.ny == b.ny && a.nz == b.nz && a.channels >= channels && b.channels >= channels);
  double sum = 0;
  for (std::size_t i = 0; i < a.voxelCount(); ++i)
    for (int c = 0; c < channels; ++c) {
      const double d = double(a.voxels[i * a.channels + c]) - b.voxels[i * b.channels + c];
      sum += d * d;
    }
  return 255.0 * std::sqrt(sum / (double(a.voxelCount()) * channels));
}

BaselineResult downsampleBaseline(const Volume& volume, int channels, std::uint64_t bytes) {
  const Volume source = firstChannels(volume, channels);
  const int n[3] = {source.nx, source.ny, source.nz};
  // The same scale on every axis, the largest whose grid fits the budget.
  const double scale = std::cbrt(double(bytes) / (double(source.voxelCount()) * channels));
  int m[3];
  for (int a = 0; a < 3; ++a) m[a] = std::clamp(int(std::floor(n[a] * scale)), 1, n[a]);

  const auto start = std::chrono::steady_clock::now();
  Volume small = source;
  for (int a = 0; a < 3; ++a) small = resampleAxis(small, a, boxTaps(n[a], m[a]));
  for (float& v : small.voxels) v = std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;  // 8-bit storage
  BaselineResult result;
  result.seconds = secondsSince(start);
  Volume back = small;
  for (int a = 0; a < 3; ++a) back = resampleAxis(back, a, catmullRomTaps(m[a], n[a]));
  result.rms = volumeRms(back, source, channels);
  result.bytes = std::uint64_t(small.voxelCount()) * channels;
  result.setting = std::to_string(m[0]) + "x" + std::to_string(m[1]) + "x" + std::to_string(m[2]);
  return result;
}

BaselineResult zfpBaseline(const Volume& volume, int channels, std::uint64_t bytes) {
  const std::size_t count = volume.voxelCount();
  const double rate = std::floor(64.0 * 8.0 * double(bytes) / (double(count) * channels)) / 64.0;
  Volume decoded(volume.nx, volume.ny, volume.nz, channels);
  std::vector<float> plane(count);
  BaselineResult result;
  for (int c = 0; c < channels; ++c) {
    for (std::size_t i = 0; i < count; ++i) plane[i] = volume.voxels[i * volume.channels + c];
    zfp_field* field = zfp_field_3d(plane.data(), zfp_type_float, std::size_t(volume.nx), std::size_t(volume.ny),
                                    std::size_t(volume.nz));
    zfp_stream* zfp = zfp_stream_open(nullptr);
    const double actualRate = zfp_stream_set_rate(zfp, rate, zfp_type_float, 3, zfp_false);
    std::vector<unsigned char> buffer(zfp_stream_maximum_size(zfp, field));
    bitstream* stream = stream_open(buffer.data(), buffer.size());
    zfp_stream_set_bit_stream(zfp, stream);

    const auto start = std::chrono::steady_clock::now();
    const std::size_t size = zfp_compress(zfp, field);
    result.seconds += secondsSince(start);
    std::fill(plane.begin(), plane.end(), 0.0f);
    zfp_stream_rewind(zfp);
    const std::size_t read = zfp_decompress(zfp, field);
    stream_close(stream);
    zfp_stream_close(zfp);
    zfp_field_free(field);
    if (size == 0 || read == 0) throw InternalError("zfp failed on channel " + std::to_string(c));

    result.bytes += size;
    result.setting = std::to_string(actualRate) + " bits/value";
    for (std::size_t i = 0; i < count; ++i) decoded.voxels[i * channels + c] = plane[i];
  }
  result.rms = volumeRms(decoded, volume, channels);
  return result;
}

}  // namespace texsynth::bench
