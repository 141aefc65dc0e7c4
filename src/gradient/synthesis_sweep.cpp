// One synthesis iteration swept in z order with bucket reuse (see synthesis_sweep.h).
//
// Cube layers advance one at a time. Cube layer kz's check points reach bucket layers [lo(kz), hi(kz)]
// (both grow with kz), so once the next layer to match starts above a bucket layer, that layer has all
// its samples. At the finest level each sample is deposited twice: pass 1 counts clusters, pass 2 (run
// for a cube layer once every bucket layer it reaches has finished pass 1) sums the samples of each
// bucket's two dominant clusters. A control layer is refitted once its buckets are complete, and its new
// values are written only when no check point still to be matched reads it, so every match sees the
// previous iteration's solid, exactly as without reuse.
#include "synthesis_sweep.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <memory>

#include "first_order_fit.h"
#include "synthesis_matching.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/core/wrap.h"

namespace texsynth::gradient_synthesis {
namespace {

constexpr std::uint8_t kNoCluster = 255;

enum class Pass { Plain, Count, Dominant };

struct Layer {
  std::vector<std::uint8_t> counts;    // pass 1: clusterCount saturating counts per bucket
  std::vector<std::uint8_t> dominant;  // 2 per bucket: the dominant clusters (kNoCluster: none)
  std::vector<float> sums;             // features sums and the sample count per bucket
};

// The bucket layers alive, and how many bytes they hold.
class Window {
 public:
  Window(const BucketGrid& grid, int features, int clusters)
      : grid_(grid), features_(features), clusters_(clusters), layers_(std::size_t(grid.buckets.z())) {}

  Layer& at(int z) {
    auto& layer = layers_[std::size_t(z)];
    if (!layer) layer = std::make_unique<Layer>();
    return *layer;
  }
  void needCounts(int z) { resize(at(z).counts, std::size_t(clusters_)); }
  void needSums(int z) { resize(at(z).sums, std::size_t(features_ + 1)); }
  void needDominant(int z) { resize(at(z).dominant, 2, kNoCluster); }
  void dropCounts(int z) { release(at(z).counts); }
  void drop(int z) {
    Layer& layer = at(z);
    release(layer.counts);
    release(layer.dominant);
    release(layer.sums);
    layers_[std::size_t(z)].reset();
  }
  std::int64_t peakBytes() const { return peak_; }

 private:
  template <typename T>
  void resize(std::vector<T>& v, std::size_t perBucket, T fill = T(0)) {
    if (!v.empty()) return;
    v.assign(std::size_t(grid_.layerSize()) * perBucket, fill);
    live_ += std::int64_t(v.size() * sizeof(T));
    peak_ = std::max(peak_, live_);
  }
  template <typename T>
  void release(std::vector<T>& v) {
    live_ -= std::int64_t(v.size() * sizeof(T));
    std::vector<T>().swap(v);
  }
  const BucketGrid& grid_;
  int features_, clusters_;
  std::vector<std::unique_ptr<Layer>> layers_;
  std::int64_t live_ = 0, peak_ = 0;
};

class Sweep {
 public:
  Sweep(const LevelContext& ctx, GradientSolid& state, const std::function<void(const ClosedLayer&)>& closed)
      : ctx_(ctx),
        state_(state),
        closed_(closed),
        grid_(state, ctx.spacing),
        window_(grid_, ctx.features, std::max(ctx.clusterCount, 1)),
        cubes_(state.controls - Vec3i::Ones()) {
    // A coarser level's buckets are h voxels apart, and so are its check points: N_C per block of h^3
    // cubes (the cube of its coarser voxels), in the blocks' first cube layer.
    step_ = ctx.spacing;
    active_ = Vec3i((cubes_.x() + step_ - 1) / step_, (cubes_.y() + step_ - 1) / step_, 0);
    // Strips of block rows deposited in parallel: strips two apart never reach the same bucket.
    const float stripVoxels = 2.0f * ctx.reach() + float(state.spacing * step_) + 2.0f * float(ctx.spacing);
    stripRows_ = int(std::ceil(stripVoxels / float(state.spacing * step_))) + 1;
  }

  void run(SweepStats& stats, Progress& progress) {
    for (next1_ = 0; next1_ < cubes_.z();) {
      matchLayer(next1_);
      progress.advance(1);
      deposit(next1_, ctx_.quantized ? Pass::Count : Pass::Plain);
      if (!ctx_.quantized) matches_.pop_front(), ++next2_;
      ++next1_;
      if (ctx_.options->bucketReuse) drain();
    }
    drain();
    TS_CHECK_MSG(nextFit_ == state_.controls.z() && pending_.empty(), "synthesis sweep left control layers unfitted");
    stats.checkPoints += checkPoints_;
    stats.peakBucketBytes = std::max(stats.peakBucketBytes, window_.peakBytes());
  }

 private:
  // Bucket layers cube layer kz can reach (a conservative bound: one bucket of slack each side).
  int lo(int kz) const {
    const float z = float(state_.spacing) * float(kz) - ctx_.reach();
    return std::max(0, int(std::floor(z / float(ctx_.spacing) + 0.5f)) - 1);
  }
  int hi(int kz) const {
    const float z = float(state_.spacing) * float(kz + step_) + ctx_.reach();
    return std::min(grid_.buckets.z() - 1, int(std::floor(z / float(ctx_.spacing) + 0.5f)) + 1);
  }
  // The lowest control layer matching cube layer kz reads.
  int readLo(int kz) const {
    const float z = float(state_.spacing) * float(kz) - ctx_.reach();
    return std::max(0, int(std::floor(z / float(state_.spacing) + 0.5f)) - 1);
  }
  // Whether no cube layer from `next` on reaches bucket layer z.
  bool complete(int next, int z) const { return next >= cubes_.z() || lo(next) > z; }

  void matchLayer(int kz) {
    const GradientSynthesisOptions& options = *ctx_.options;
    const int perCube = options.checkPoints;
    std::vector<CheckPoint> points(kz % step_ == 0 ? std::size_t(active_.x()) * active_.y() * perCube : 0);
    const Vec3f last = (state_.voxels - Vec3i::Ones()).cast<float>();
    parallelForChunks(0, std::int64_t(points.size()), 16, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t n = begin; n < end; ++n) {
        const std::int64_t cube = n / perCube;
        const int cx = int(cube % active_.x()) * step_, cy = int(cube / active_.x()) * step_;
        CheckPoint& cp = points[std::size_t(n)];
        const std::uint64_t key = hashKey(options.seed, latticeId(cx, cy, kz),
                                          std::uint64_t(ctx_.level * 64 + ctx_.iteration), std::uint64_t(n % perCube));
        const Vec3f jitter(uniform01(mix64(key)), uniform01(mix64(key + 1)), uniform01(mix64(key + 2)));
        cp.position =
            (float(state_.spacing) * (Vec3f(float(cx), float(cy), float(kz)) + float(step_) * jitter)).cwiseMin(last);
        if (options.orientation) cp.frame = options.orientation(cp.position).normalized().toRotationMatrix();
        if (options.exemplarSetOf) {
          cp.set = options.exemplarSetOf(cp.position);
          TS_CHECK_MSG(cp.set >= 0 && cp.set < int(ctx_.sets.size()), "exemplar set rule out of range");
        }
        matchCheckPoint(ctx_, state_, cp);
      }
    });
    checkPoints_ += std::int64_t(points.size());
    matches_.push_back(std::move(points));
  }

  void deposit(int kz, Pass pass) {
    const std::vector<CheckPoint>& points = matches_[std::size_t(kz - next2_)];
    if (points.empty()) return;
    for (int z = lo(kz); z <= hi(kz); ++z) {
      if (pass == Pass::Count)
        window_.needCounts(z);
      else
        window_.needSums(z);
    }
    const int perRow = active_.x() * ctx_.options->checkPoints;
    const int strips = (active_.y() + stripRows_ - 1) / stripRows_;
    for (int parity = 0; parity < 2; ++parity)
      parallelFor(0, (strips + 1 - parity) / 2, [&](std::int64_t s) {
        const int strip = int(2 * s + parity);
        const int rowEnd = std::min(active_.y(), (strip + 1) * stripRows_);
        for (std::int64_t n = std::int64_t(strip) * stripRows_ * perRow; n < std::int64_t(rowEnd) * perRow; ++n)
          depositPoint(points[std::size_t(n)], pass, kz);
      });
  }

  void depositPoint(const CheckPoint& cp, Pass pass, int kz) {
    const GradientExemplars::Impl& set = *ctx_.sets[std::size_t(cp.set)];
    const bool aligned = cp.frame.isIdentity();
    for (int plane = 0; plane < 3; ++plane) {
      if (cp.pixel[plane] < 0) continue;
      if (aligned)
        depositPatch<true>(cp, set, plane, pass, kz);
      else
        depositPatch<false>(cp, set, plane, pass, kz);
    }
  }

  // One matched patch's N x N samples into their buckets. Aligned (no field): bucket indices step by whole
  // buckets along the plane's axes, so no sample needs floating point.
  template <bool kAligned>
  void depositPatch(const CheckPoint& cp, const GradientExemplars::Impl& set, int plane, Pass pass, int kz) {
    const int h = ctx_.spacing, r = ctx_.radius(), f = ctx_.features;
    const float inverse = 1.0f / float(h);
    const int zLo = lo(kz), zHi = hi(kz);
    const Image& image = set.at(SlicePlane(plane), ctx_.level).level->image;
    const std::uint8_t* labels = set.labels[std::size_t(plane)].data();
    const int clusterOffset = ctx_.clusterOffset[std::size_t(cp.set)];
    const int ex = cp.pixel[plane] % image.width, ey = cp.pixel[plane] / image.width;
    int u, v;
    planeAxes(plane, u, v);
    const Vec3f du = cp.frame.col(u) * float(h), dv = cp.frame.col(v) * float(h);
    Vec3i centre = Vec3i::Zero();
    for (int a = 0; a < 3; ++a) centre[a] = int(std::floor(cp.position[a] * inverse + 0.5f));
    int columns[kMaxNeighborhoodSize], rows[kMaxNeighborhoodSize];  // the patch's exemplar pixels, wrapped
    for (int k = -r; k <= r; ++k) {
      columns[k + r] = wrapIndex(std::int64_t(ex) + std::int64_t(k) * h, image.width);
      rows[k + r] = wrapIndex(std::int64_t(ey) + std::int64_t(k) * h, image.height);
    }
    const auto sample = [&](int i, int j) {
      Vec3i b;
      if constexpr (kAligned) {
        b = centre;
        b[u] += i, b[v] += j;
      } else {
        const Vec3f q = (cp.position + float(i) * du + float(j) * dv) * inverse;
        for (int a = 0; a < 3; ++a) b[a] = int(std::floor(q[a] + 0.5f));
      }
      if (b.x() < 0 || b.y() < 0 || b.z() < 0 || b.x() >= grid_.buckets.x() || b.y() >= grid_.buckets.y() ||
          b.z() >= grid_.buckets.z())
        return;
      TS_CHECK_MSG(b.z() >= zLo && b.z() <= zHi, "a synthesis sample fell outside its bucket window");
      const int px = columns[i + r], py = rows[j + r];
      const std::size_t pixel = std::size_t(py) * image.width + std::size_t(px);
      const std::size_t bucket = std::size_t(b.y()) * grid_.buckets.x() + std::size_t(b.x());
      Layer& layer = window_.at(b.z());
      if (pass == Pass::Count) {
        std::uint8_t& count = layer.counts[bucket * std::size_t(ctx_.clusterCount) + clusterOffset + labels[pixel]];
        if (count < 255) ++count;
        return;
      }
      if (pass == Pass::Dominant) {
        const std::uint8_t cluster = std::uint8_t(clusterOffset + labels[pixel]);
        if (cluster != layer.dominant[2 * bucket] && cluster != layer.dominant[2 * bucket + 1]) return;
      }
      float* sum = &layer.sums[bucket * std::size_t(f + 1)];
      const float* value = image.pixel(px, py);
      for (int c = 0; c < f; ++c) sum[c] += value[c];
      sum[f] += 1.0f;
    };
    // The inner loop runs along the slice axis with the closest buckets in memory: x for the y slice (v = x),
    // u otherwise (x for z slices, y for x slices). Aligned patches put one sample per bucket, so the order
    // never changes a sum.
    if (kAligned && plane == int(SlicePlane::Y)) {
      for (int i = -r; i <= r; ++i)
        for (int j = -r; j <= r; ++j) sample(i, j);
    } else {
      for (int j = -r; j <= r; ++j)
        for (int i = -r; i <= r; ++i) sample(i, j);
    }
  }

  // Pass 1 of bucket layer z is complete: keep its two dominant clusters, drop the counts.
  void finishCounts(int z) {
    window_.needDominant(z);
    Layer& layer = window_.at(z);
    if (layer.counts.empty()) return;  // no check point reached it
    const int k = ctx_.clusterCount;
    parallelForChunks(0, grid_.layerSize(), 4096, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t b = begin; b < end; ++b) {
        const std::uint8_t* counts = &layer.counts[std::size_t(b) * k];
        int first = -1, second = -1;
        for (int c = 0; c < k; ++c) {
          if (counts[c] == 0) continue;
          if (first < 0 || counts[c] > counts[first])
            second = first, first = c;
          else if (second < 0 || counts[c] > counts[second])
            second = c;
        }
        layer.dominant[2 * std::size_t(b)] = first < 0 ? kNoCluster : std::uint8_t(first);
        layer.dominant[2 * std::size_t(b) + 1] = second < 0 ? kNoCluster : std::uint8_t(second);
      }
    });
    window_.dropCounts(z);
  }

  // Everything the samples so far allow: pass-1 closures, pass-2 deposits, fits, commits.
  void drain() {
    if (ctx_.quantized) {
      while (countsDone_ < grid_.buckets.z() && complete(next1_, countsDone_)) finishCounts(countsDone_++);
      while (next2_ < next1_ && countsDone_ > hi(next2_)) {
        deposit(next2_, Pass::Dominant);
        matches_.pop_front();
        ++next2_;
      }
    }
    while (nextFit_ < state_.controls.z() && complete(next2_, grid_.ownedEnd(2, nextFit_) - 1)) fit(nextFit_++);
    while (!pending_.empty() && (next1_ >= cubes_.z() || pending_.begin()->first < readLo(next1_))) {
      const auto& [kc, values] = *pending_.begin();
      std::copy(values.begin(), values.end(),
                state_.positive.begin() + std::ptrdiff_t(state_.controlIndex(0, 0, kc) * state_.setSize()));
      pending_.erase(pending_.begin());
    }
  }

  // Eq. 2 for control layer kc from its complete buckets; the layers are then freed.
  void fit(int kc) {
    const int zBegin = grid_.ownedBegin(2, kc), zEnd = grid_.ownedEnd(2, kc), f = ctx_.features;
    if (closed_) announceClosed(zBegin, zEnd);
    const std::size_t setSize = std::size_t(state_.setSize());
    std::vector<float> values(std::size_t(state_.controls.x()) * state_.controls.y() * setSize);
    const float d = float(state_.spacing), h = float(ctx_.spacing);
    std::vector<const Layer*> layers;
    for (int bz = zBegin; bz < zEnd; ++bz) layers.push_back(layerIfSums(bz));
    parallelFor(0, state_.controls.y(), [&](std::int64_t j) {
      for (int i = 0; i < state_.controls.x(); ++i) {
        FirstOrderFit fitter(f);
        for (int bz = zBegin; bz < zEnd; ++bz) {
          const Layer* layer = layers[std::size_t(bz - zBegin)];
          if (!layer) continue;
          for (int by = grid_.ownedBegin(1, int(j)); by < grid_.ownedEnd(1, int(j)); ++by)
            for (int bx = grid_.ownedBegin(0, i); bx < grid_.ownedEnd(0, i); ++bx) {
              const float* sum = &layer->sums[(std::size_t(by) * grid_.buckets.x() + bx) * std::size_t(f + 1)];
              if (sum[f] <= 0.0f) continue;
              float average[FirstOrderFit::kMaxChannels];
              for (int c = 0; c < f; ++c) average[c] = sum[c] / sum[f];
              fitter.add((h * float(bx) - d * float(i)) / d, (h * float(by) - d * float(j)) / d,
                         (h * float(bz) - d * float(kc)) / d, average);
            }
        }
        float* out = &values[(std::size_t(j) * state_.controls.x() + std::size_t(i)) * setSize];
        if (fitter.weight() > 0)
          fitter.solve(out);
        else  // no sample reached it: keep what it had
          std::copy_n(&state_.positive[std::size_t(state_.controlIndex(i, int(j), kc)) * setSize], setSize, out);
      }
    });
    for (int bz = zBegin; bz < zEnd; ++bz) window_.drop(bz);
    pending_.emplace(kc, std::move(values));
  }

  const Layer* layerIfSums(int z) {
    const Layer& layer = window_.at(z);
    return layer.sums.empty() ? nullptr : &layer;
  }

  void announceClosed(int zBegin, int zEnd) {
    const int f = ctx_.features;
    std::vector<float> averages(std::size_t(grid_.layerSize()) * f);
    std::vector<std::uint8_t> filled(std::size_t(grid_.layerSize()));
    for (int z = zBegin; z < zEnd; ++z) {
      const Layer* layer = layerIfSums(z);
      for (std::int64_t b = 0; b < grid_.layerSize(); ++b) {
        const float* sum = layer ? &layer->sums[std::size_t(b) * (f + 1)] : nullptr;
        filled[std::size_t(b)] = sum && sum[f] > 0.0f ? 1 : 0;
        for (int c = 0; c < f; ++c) averages[std::size_t(b) * f + c] = filled[std::size_t(b)] ? sum[c] / sum[f] : 0.0f;
      }
      closed_({z, averages.data(), filled.data()});
    }
  }

  const LevelContext& ctx_;
  GradientSolid& state_;
  const std::function<void(const ClosedLayer&)>& closed_;
  BucketGrid grid_;
  Window window_;
  Vec3i cubes_;
  int step_ = 1;       // cubes between check-point blocks along each axis
  Vec3i active_;       // blocks along x and y
  int stripRows_ = 1;  // block rows per deposit strip
  int next1_ = 0, next2_ = 0, nextFit_ = 0, countsDone_ = 0;
  std::deque<std::vector<CheckPoint>> matches_;  // cube layers next2_ .. next1_ - 1
  std::map<int, std::vector<float>> pending_;    // fitted control layers not yet written
  std::int64_t checkPoints_ = 0;
};

}  // namespace

void sweepIteration(const LevelContext& ctx, GradientSolid& state, SweepStats& stats,
                    const std::function<void(const ClosedLayer&)>& closed, Progress& progress) {
  Sweep(ctx, state, closed).run(stats, progress);
}

}  // namespace texsynth::gradient_synthesis
