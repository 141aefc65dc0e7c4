// Lazy solid synthesis, correction (§4.3): a voxel gathers three N x N neighbourhoods of colours
// in the planes of its local frame (nearest voxel, its colour read where its coordinate puts the
// exact rotated tap; on coarse levels with a field, positions integrated along the field and
// colours read trilinearly), projects each with that plane's PCA, and
// takes among the candidate triples proposed by its in-plane neighbours (the paper's reduced
// S(v)) the one whose three exemplar neighbourhoods are nearest, summed over the planes. A step
// computes all its results from the state before it, then writes them, so results never depend
// on scheduling. Per voxel, each distinct candidate triple is measured once, and a cheap
// vectorized bound rejects most of them before the exact (ordered) distance.
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"
#include "texsynth/solid/lazy_blocks.h"

namespace texsynth::lazy {
namespace {

constexpr std::int64_t kBlocksPerChunk = 8;
constexpr int kHead = 8;  // leading PCA dimensions per plane that the quick bound tests first
constexpr std::array<int, 2> kNoShift = {0, 0};

// Local offset of in-plane position (a, b) = (u, v) of each plane: I_xy (x, y), I_yz (y, z), I_zx (z, x).
Vec3f planeOffset(int plane, int a, int b) {
  if (plane == 0) return {float(a), float(b), 0.0f};
  if (plane == 1) return {0.0f, float(a), float(b)};
  return {float(b), 0.0f, float(a)};
}

std::int32_t component(const CoordinateTriple& t, int plane) {
  return plane == 0 ? t.xy : plane == 1 ? t.yz : t.zx;
}

Vec3i roundVector(const Vec3f& v) {
  return {int(std::floor(v.x() + 0.5f)), int(std::floor(v.y() + 0.5f)), int(std::floor(v.z() + 0.5f))};
}

// The local axes of each plane's (a, b), as planeOffset: I_xy (x, y), I_yz (y, z), I_zx (z, x).
constexpr int kPlaneAxes[3][2] = {{0, 1}, {1, 2}, {2, 0}};

// The 3x3 in-plane offsets with (0,0) first: a voxel's own proposals win ties.
constexpr int kOffsets[9][2] = {{0, 0}, {-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}};

// The blocks around one block whose state before a step may be read, as a dense table.
class BlockNeighborhood {
 public:
  BlockNeighborhood(const LevelContext& ctx, const WorkSet& set, const Vec3i& block, int radius, int step)
      : set_(set), channels_(ctx.channels), span_((kB - 1 + radius) / kB), side_(2 * span_ + 1) {
    for (const WorkSet::Version& snapshot : set.snapshots) {
      TS_CHECK(snapshot.version >= 0 && std::size_t(snapshot.version) < byVersion_.size());
      byVersion_[std::size_t(snapshot.version)] = &snapshot.blocks;
    }
    table_.resize(std::size_t(side_) * side_ * side_);
    for (int z = 0; z < side_; ++z)
      for (int y = 0; y < side_; ++y)
        for (int x = 0; x < side_; ++x) {
          const Vec3i stored = ctx.storedBlock(block + Vec3i(x, y, z) - Vec3i::Constant(span_));
          const std::int32_t i = set.indexOf(blockKey(stored.x(), stored.y(), stored.z()));
          table_[std::size_t((z * side_ + y) * side_ + x)] =
              i >= 0 && set.lastLayer[std::size_t(i)] >= step - 1 ? i : -1;
        }
  }
  // Voxel at `offset` from the voxel at `local` (0..kB-1 per axis) of the centre block, as
  // table index * kBlockVoxels + slot; -1 if its block may not be read.
  int locate(const Vec3i& local, const Vec3i& offset) const {
    const Vec3i u = local + offset + Vec3i::Constant(span_ * kB);  // >= 0 within the radius
    const int t = ((u.z() / kB) * side_ + u.y() / kB) * side_ + u.x() / kB;
    if (table_[std::size_t(t)] < 0) return -1;
    return t * kBlockVoxels + ((u.z() % kB) * kB + u.y() % kB) * kB + u.x() % kB;
  }
  const WorkBlock& block(int located) const { return set_.blocks[index(located)]; }
  // A located voxel's colours in `plane` and its triple: now (version < 0), or its snapshot of `version`.
  const float* colors(int located, int version, int plane) const {
    const std::size_t at = colorIndex(plane, located % kBlockVoxels, channels_);
    return (version < 0 ? block(located).colors.data() : snapshot(version, located).colors.data()) + at;
  }
  const CoordinateTriple& triple(int located, int version) const {
    const std::size_t slot = std::size_t(located % kBlockVoxels);
    return version < 0 ? block(located).triples[slot] : snapshot(version, located).triples[slot];
  }

 private:
  std::size_t index(int located) const { return std::size_t(table_[std::size_t(located / kBlockVoxels)]); }
  const WorkSet::Snapshot& snapshot(int version, int located) const {
    return (*byVersion_[std::size_t(version)])[index(located)];
  }

  const WorkSet& set_;
  std::array<const std::vector<WorkSet::Snapshot>*, 16> byVersion_{};  // snapshots by version
  int channels_, span_, side_;
  std::vector<std::int32_t> table_;
};

// Open-addressing set of the triples already measured for one voxel (a generation stamp
// clears it in O(1)): coherent neighbours propose the same triples over and over.
class TripleSet {
 public:
  // Returns true if `t` was not in the set (and inserts it).
  bool insert(const CoordinateTriple& t) {
    std::uint32_t h =
        (std::uint32_t(t.xy) * 0x9E3779B1u) ^ (std::uint32_t(t.yz) * 0x85EBCA77u) ^ (std::uint32_t(t.zx) * 0xC2B2AE3Du);
    for (h = (h ^ (h >> 15)) & kMask;; h = (h + 1) & kMask) {
      Entry& e = entries_[h];
      if (e.stamp != stamp_) {
        e = {t, stamp_};
        return true;
      }
      if (e.triple == t) return false;
    }
  }
  void clear() {
    if (++stamp_ == 0) {
      for (Entry& e : entries_) e.stamp = 0;
      stamp_ = 1;
    }
  }

 private:
  static constexpr std::uint32_t kSize = 1024, kMask = kSize - 1;  // > 27 * 64 / 2 + 1 entries
  struct Entry {
    CoordinateTriple triple;
    std::uint32_t stamp = 0;
  };
  std::array<Entry, kSize> entries_{};
  std::uint32_t stamp_ = 1;
};

class VoxelCorrector {
 public:
  explicit VoxelCorrector(const LevelContext& ctx)
      : ctx_(ctx),
        n_(ctx.neighborhoodSize),
        r_(n_ / 2),
        integrated_(ctx.integrated()),
        readRadius_(ctx.readRadius()),
        reach_(float(r_) * 1.41421356f) {
    for (int p = 0; p < 3; ++p) {
      TS_CHECK(ctx.planes[p]->pca.inputDimension == n_ * n_ * ctx.channels);
      query_[p].resize(std::size_t(ctx.planes[p]->pca.outputDimension));
      headFits_ = headFits_ && ctx.planes[p]->pca.outputDimension >= kHead;
    }
    TS_CHECK(ctx.triples->count <= 64);
    buffer_.resize(std::size_t(n_) * n_ * ctx.channels);
    offsets_.resize(std::size_t(3 * (n_ * n_ + 9)));
    shifts_.resize(std::size_t(3 * n_ * n_));
    located_.resize(offsets_.size());
    if (integrated_) taps_.resize(std::size_t(3 * n_ * n_)), walk_.resize(std::size_t(n_));
  }

  std::int64_t comparisons() const { return comparisons_; }

  // Corrects voxel `slot` of `self` (the centre block of `around`) into `out`; false (and `out`
  // untouched) if it would read a block that may not be read.
  bool correct(const BlockNeighborhood& around, const WorkBlock& self, int slot, const StepReads& reads,
               CoordinateTriple& out) {
    setOffsets(self.frames[std::size_t(slot)]);
    const Vec3i local(slot % kB, slot / kB % kB, slot / (kB * kB));
    sources_ = reads.sourcesFor(self.origin + local);
    windowRadius_ = reads.radius;
    // Integrated levels locate only the candidate sources here (the taps are sampled below).
    for (std::size_t i = integrated_ ? std::size_t(3 * n_ * n_) : 0; i < offsets_.size(); ++i)
      if ((located_[i] = around.locate(local, offsets_[i])) < 0) return false;

    const int c = ctx_.channels, taps = n_ * n_;
    if (integrated_ && !setIntegratedTaps(around, local)) return false;
    for (int p = 0; p < 3; ++p) {
      float* write = buffer_.data();
      for (int k = 0; k < taps; ++k) {
        if (integrated_) {
          if (!sampleTrilinear(around, local, p, taps_[std::size_t(p * taps + k)], write)) return false;
          write += c;
          continue;
        }
        const std::size_t tap = std::size_t(p * taps + k);
        const float* color = shifts_[tap] == kNoShift ? around.colors(located_[tap], versionAt(offsets_[tap]), p)
                                                      : shiftedColor(around, tap, p);
        for (int i = 0; i < c; ++i) *write++ = color[i];  // c is small: no memmove call
      }
      ctx_.planes[p]->pca.project(buffer_.data(), query_[p].data());
    }
    const CoordinateTriple current = self.triples[std::size_t(slot)];
    CoordinateTriple best = current;
    float bestDistance = distance(current, std::numeric_limits<float>::infinity());
    ++comparisons_;
    seen_.clear();
    seen_.insert(current);
    const CandidateTriples& candidates = *ctx_.triples;
    for (int p = 0; p < 3; ++p) {
      std::int32_t proposed[9];
      int proposals = 0;
      for (int k = 0; k < 9; ++k) {
        const std::size_t source = std::size_t(3 * taps + p * 9 + k);
        const std::int32_t pixel = component(around.triple(located_[source], versionAt(offsets_[source])), p);
        // [T_P(v + d) - h P(d)], d the neighbour's offset in the local frame (in the plane's (u, v)).
        const std::array<int, 2>& back = sourceShifts_[std::size_t(p * 9 + k)];
        const std::int32_t sourcePixel = offsetPixel(pixel, ctx_.width, ctx_.height, back[0], back[1]);
        if (std::find(proposed, proposed + proposals, sourcePixel) != proposed + proposals) continue;
        proposed[proposals++] = sourcePixel;
        const CoordinateTriple* triples = candidates.at(Plane(p), sourcePixel);
        const float* errors = candidates.errorsAt(Plane(p), sourcePixel);
        for (int j = 0; j < candidates.count; ++j) {
          // A triple seen before cannot win now: it lost (or tied) against a best no worse.
          if (!std::isfinite(errors[j]) || !seen_.insert(triples[j])) continue;
          ++comparisons_;
          if (surelyNotBelow(triples[j], bestDistance)) continue;
          const float dist = distance(triples[j], bestDistance);
          if (dist < bestDistance) bestDistance = dist, best = triples[j];
        }
      }
    }
    out = best;
    return true;
  }

 private:
  // The rounded read offsets of a voxel with this frame: 3 planes x N^2 neighbourhood taps, then
  // 3 planes x 9 candidate sources. Recomputed only when the frame changes (never for a constant field).
  void setOffsets(const Mat3f& frame) {
    if (valid_ && frame == frame_) return;
    frame_ = frame;
    valid_ = true;
    std::size_t i = 0;
    for (int p = 0; p < 3; ++p)
      for (int b = -r_; b <= r_; ++b)
        for (int a = -r_; a <= r_; ++a) {
          // The rounded tap lies off the exact one by a fraction of a voxel; in the plane that is
          // this many exemplar pixels (h per voxel), the shift shiftedColor applies.
          const Vec3f exact = planeOffset(p, a, b);
          offsets_[i] = roundVector(frame * exact);
          const Vec3i shift =
              roundVector(float(ctx_.spacing) * (exact - frame.transpose() * offsets_[i].cast<float>()));
          shifts_[i++] = {shift[kPlaneAxes[p][0]], shift[kPlaneAxes[p][1]]};
        }
    for (int p = 0; p < 3; ++p)
      for (int k = 0; k < 9; ++k) {
        // The rounded neighbour's own local offset (not the intended one) says where its
        // coordinate leads back to.
        offsets_[i] = roundVector(frame * planeOffset(p, kOffsets[k][0], kOffsets[k][1]));
        const Vec3i local = roundVector(float(ctx_.spacing) * (frame.transpose() * offsets_[i++].cast<float>()));
        sourceShifts_[std::size_t(p * 9 + k)] = {-local[kPlaneAxes[p][0]], -local[kPlaneAxes[p][1]]};
      }
  }

  // Plane p's colour for tap `tap` whose rounded voxel lies off the exact offset (a rotated
  // frame): the neighbour's plane-p coordinate moved by the residual, as if the neighbour sat at
  // the exact offset (Lefebvre and Hoppe 2006, anisometric synthesis). Nearest-voxel colours
  // alone misalign a rotated neighbourhood by up to half a voxel, which thin features such as a
  // weave's threads do not survive.
  const float* shiftedColor(const BlockNeighborhood& around, std::size_t tap, int p) const {
    const std::int32_t pixel = offsetPixel(component(around.triple(located_[tap], versionAt(offsets_[tap])), p),
                                           ctx_.width, ctx_.height, shifts_[tap][0], shifts_[tap][1]);
    return ctx_.planes[p]->image.pixels.data() + std::size_t(pixel) * std::size_t(ctx_.channels);
  }

  // The version the voxel's history window reads at `offset` (-1: the neighbour's current state).
  int versionAt(const Vec3i& offset) const {
    const int d = 2 * windowRadius_ + 1;
    return sources_[((offset.z() + windowRadius_) * d + (offset.y() + windowRadius_)) * d + offset.x() + windowRadius_];
  }

  // The frame of the voxel nearest `offset` (clamped to the read radius); null if unreadable.
  const Mat3f* frameNear(const BlockNeighborhood& around, const Vec3i& local, const Vec3f& offset) const {
    const Vec3i o = roundVector(offset).cwiseMax(Vec3i::Constant(-readRadius_)).cwiseMin(Vec3i::Constant(readRadius_));
    const int at = around.locate(local, o);
    return at < 0 ? nullptr : &around.block(at).frames[std::size_t(at % kBlockVoxels)];
  }

  // One unit step along local axis `axis` (times `sign`) from `x`, midpoint rule on the
  // nearest voxels' frames. False if a frame cannot be read.
  bool step(const BlockNeighborhood& around, const Vec3i& local, int axis, float sign, Vec3f& x) const {
    const Mat3f* start = frameNear(around, local, x);
    if (!start) return false;
    const Mat3f* middle = frameNear(around, local, x + 0.5f * sign * start->col(axis));
    if (!middle) return false;
    x += sign * middle->col(axis);
    return true;
  }

  // Coarse levels: each plane's tap (a, b) lies |a| steps along the plane's first local axis
  // and then |b| steps along its second, so the neighbourhood bends with the field (numerical
  // integration along the directions, §4.3). Offsets are clamped to sqrt(2) N/2, the reach the
  // plan allows for. Taps in setOffsets' order (b outer, a inner).
  bool setIntegratedTaps(const BlockNeighborhood& around, const Vec3i& local) {
    for (int p = 0; p < 3; ++p) {
      const int axisA = kPlaneAxes[p][0], axisB = kPlaneAxes[p][1];
      walk_[std::size_t(r_)] = Vec3f::Zero();
      for (float sign : {-1.0f, 1.0f}) {
        Vec3f x = Vec3f::Zero();
        for (int i = 1; i <= r_; ++i) {
          if (!step(around, local, axisA, sign, x)) return false;
          walk_[std::size_t(r_ + int(sign) * i)] = x;
        }
      }
      for (int a = -r_; a <= r_; ++a) {
        Vec3f* column = &taps_[std::size_t(p * n_ * n_ + (a + r_))];
        column[std::size_t(r_ * n_)] = walk_[std::size_t(a + r_)];
        for (float sign : {-1.0f, 1.0f}) {
          Vec3f x = walk_[std::size_t(a + r_)];
          for (int i = 1; i <= r_; ++i) {
            if (!step(around, local, axisB, sign, x)) return false;
            column[std::size_t((r_ + int(sign) * i) * n_)] = x;
          }
        }
      }
    }
    for (Vec3f& tap : taps_) {
      const float length = tap.norm();
      if (length > reach_) tap *= reach_ / length;
    }
    return true;
  }

  // Plane p's colour at a fractional offset: trilinear over the 8 voxels around it, into out[channels].
  bool sampleTrilinear(const BlockNeighborhood& around, const Vec3i& local, int p, const Vec3f& offset,
                       float* out) const {
    const Vec3f base(std::floor(offset.x()), std::floor(offset.y()), std::floor(offset.z()));
    const Vec3f f = offset - base;
    const Vec3i corner0 = base.cast<int>();
    const int c = ctx_.channels;
    for (int i = 0; i < c; ++i) out[i] = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3i d(corner & 1, corner >> 1 & 1, corner >> 2 & 1);
      const float w = (d.x() ? f.x() : 1.0f - f.x()) * (d.y() ? f.y() : 1.0f - f.y()) * (d.z() ? f.z() : 1.0f - f.z());
      if (w == 0.0f) continue;
      const int at = around.locate(local, corner0 + d);
      if (at < 0) return false;
      const float* color = around.colors(at, versionAt(corner0 + d), p);
      for (int i = 0; i < c; ++i) out[i] += w * color[i];
    }
    return true;
  }

  // A quick test that distance(t) >= bound, summing in 8 lanes (vectorized): first the leading
  // kHead PCA dimensions of all three planes (the largest variances, so most candidates fail
  // here), then the rest plane by plane. Both sums of these <= 60 non-negative terms are within
  // 60 ulp-sized relative errors of the exact one, so lanes * (1 - 1e-4) >= bound implies the
  // ordered sum >= bound: results stay bit-identical and the ordered sum runs only for the few
  // candidates near the best.
  bool surelyNotBelow(const CoordinateTriple& t, float bound) const {
    float lanes[kHead] = {};
    const float* targets[3];
    if (!headFits_) return false;  // too few dimensions to split: the exact distance decides
    for (int p = 0; p < 3; ++p) {
      targets[p] = ctx_.planes[p]->projectedAt(component(t, p));
      const float* query = query_[p].data();
      for (int j = 0; j < kHead; ++j) {
        const float d = query[j] - targets[p][j];
        lanes[j] += d * d;
      }
    }
    const auto total = [&lanes] {
      return ((lanes[0] + lanes[4]) + (lanes[1] + lanes[5])) + ((lanes[2] + lanes[6]) + (lanes[3] + lanes[7]));
    };
    if (total() * (1.0f - 1e-4f) >= bound) return true;
    float tail = 0;
    for (int p = 0; p < 3; ++p) {
      const float* query = query_[p].data();
      const int dims = ctx_.planes[p]->pca.outputDimension;
      int i = kHead;
      for (; i + kHead <= dims; i += kHead)
        for (int j = 0; j < kHead; ++j) {
          const float d = query[i + j] - targets[p][i + j];
          lanes[j] += d * d;
        }
      for (; i < dims; ++i) {
        const float d = query[i] - targets[p][i];
        tail += d * d;
      }
      if ((total() + tail) * (1.0f - 1e-4f) >= bound) return true;
    }
    return false;
  }

  // Sum over the planes of the squared PCA distance; stops early once past `bound`.
  float distance(const CoordinateTriple& t, float bound) const {
    float sum = 0;
    for (int p = 0; p < 3; ++p) {
      const ExemplarLevel& level = *ctx_.planes[p];
      const float* target = level.projectedAt(component(t, p));
      const float* query = query_[p].data();
      for (int i = 0; i < level.pca.outputDimension; ++i) {
        const float d = query[i] - target[i];
        sum += d * d;
      }
      if (sum >= bound) return sum;
    }
    return sum;
  }

  const LevelContext& ctx_;
  int n_, r_;
  std::int64_t comparisons_ = 0;  // neighbourhood comparisons (candidates measured), all voxels
  bool integrated_;
  bool headFits_ = true;  // every plane keeps >= kHead PCA dimensions (surelyNotBelow's first test)
  int readRadius_;
  float reach_;  // largest integrated tap offset, sqrt(2) N/2
  std::vector<float> buffer_, query_[3];
  std::vector<Vec3f> taps_, walk_;  // integrated tap offsets (3 N^2), one walk along an axis (N)
  std::vector<Vec3i> offsets_;
  std::vector<std::array<int, 2>> shifts_;             // per neighbourhood tap: exemplar shift (shiftedColor)
  std::array<std::array<int, 2>, 27> sourceShifts_{};  // per candidate source: back to this voxel
  std::vector<int> located_;
  const std::int8_t* sources_ = nullptr;  // the voxel's read table (StepReads)
  int windowRadius_ = 0;
  Mat3f frame_;
  bool valid_ = false;
  TripleSet seen_;
};

}  // namespace

StepCounts correctStep(const LevelContext& ctx, WorkSet& set, int step, const StepReads& reads,
                       const GridPhase* phase) {
  const int radius = ctx.readRadius();
  TS_CHECK(reads.radius >= radius);
  const int s = reads.s, voxelClass = reads.voxelClass;
  for (int version : reads.snapshotVersions)
    TS_CHECK(std::any_of(set.snapshots.begin(), set.snapshots.end(),
                         [&](const WorkSet::Version& v) { return v.version == version; }));
  std::vector<std::int32_t> targets;
  for (std::size_t i = 0; i < set.keys.size(); ++i)
    if (phase ? phase->correct[i] != 0 : set.lastLayer[i] >= step) targets.push_back(std::int32_t(i));
  // Results first (reading only the state before the step), then written back.
  std::vector<CoordinateTriple> results(targets.size() * kBlockVoxels);
  std::vector<std::uint64_t> corrected(targets.size(), 0);  // bit per slot
  std::atomic<std::int64_t> comparisons{0};
  parallelForChunks(0, std::int64_t(targets.size()), kBlocksPerChunk, [&](std::int64_t begin, std::int64_t end) {
    auto corrector = std::make_unique<VoxelCorrector>(ctx);
    for (std::int64_t i = begin; i < end; ++i) {
      const std::size_t index = std::size_t(targets[std::size_t(i)]);
      const WorkBlock& in = set.blocks[index];
      const BlockNeighborhood around(ctx, set, blockIndex(set.keys[index]), radius, step);
      for (int slot = 0; slot < kBlockVoxels; ++slot) {
        const Vec3i v = in.origin + Vec3i(slot % kB, slot / kB % kB, slot / (kB * kB));
        if (voxelClass >= 0 && subpassClassOf(v, s) != voxelClass) continue;
        if (phase && !(phase->correct[index] >> slot & 1)) continue;
        if (corrector->correct(around, in, slot, reads, results[std::size_t(i) * kBlockVoxels + std::size_t(slot)]))
          corrected[std::size_t(i)] |= std::uint64_t(1) << slot;
      }
    }
    comparisons += corrector->comparisons();
  });
  parallelForChunks(0, std::int64_t(targets.size()), kBlocksPerChunk, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) {
      WorkBlock& out = set.blocks[std::size_t(targets[std::size_t(i)])];
      for (int slot = 0; slot < kBlockVoxels; ++slot) {
        if (!(corrected[std::size_t(i)] >> slot & 1)) continue;
        const CoordinateTriple t = results[std::size_t(i) * kBlockVoxels + std::size_t(slot)];
        out.triples[std::size_t(slot)] = t;
        ctx.color(t, out.colors.data(), slot);
      }
    }
  });
  StepCounts counts;
  for (std::uint64_t bits : corrected) counts.corrections += std::popcount(bits);
  counts.comparisons = comparisons;
  return counts;
}

}  // namespace texsynth::lazy
