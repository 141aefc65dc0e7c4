// Lazy solid synthesis, correction (§4.3): a voxel gathers three N x N neighbourhoods of colours
// in the planes of its local frame (nearest voxel), projects each with that plane's PCA, and
// takes among the candidate triples proposed by its in-plane neighbours (the paper's reduced
// S(v)) the one whose three exemplar neighbourhoods are nearest, summed over the planes. A step
// reads only the state before it (double buffering), so results never depend on scheduling.
#include <algorithm>
#include <cmath>
#include <limits>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"
#include "texsynth/solid/lazy_blocks.h"

namespace texsynth::lazy {
namespace {

constexpr std::int64_t kBlocksPerChunk = 8;

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

// The 3x3 in-plane offsets with (0,0) first: a voxel's own proposals win ties.
constexpr int kOffsets[9][2] = {{0, 0}, {-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}};

// Reads voxels of `before` around one block through a table of the neighbouring blocks.
class BlockNeighborhood {
 public:
  BlockNeighborhood(const WorkSet& before, const Vec3i& block, int radius)
      : span_((kB - 1 + radius) / kB), side_(2 * span_ + 1), base_(block) {
    table_.resize(std::size_t(side_) * side_ * side_);
    for (int z = 0; z < side_; ++z)
      for (int y = 0; y < side_; ++y)
        for (int x = 0; x < side_; ++x)
          table_[std::size_t((z * side_ + y) * side_ + x)] =
              before.find(blockKey(block.x() + x - span_, block.y() + y - span_, block.z() + z - span_));
  }
  // The block and slot of voxel u (absolute); it must be within the radius.
  std::pair<const WorkBlock*, int> at(const Vec3i& u) const {
    const Vec3i b(floorDiv(u.x(), kB), floorDiv(u.y(), kB), floorDiv(u.z(), kB));
    const Vec3i t = b - base_ + Vec3i::Constant(span_);
    const WorkBlock* block = table_[std::size_t((t.z() * side_ + t.y()) * side_ + t.x())];
    TS_CHECK_MSG(block != nullptr, "lazy correction read a voxel outside its planned region");
    const Vec3i local = u - b * kB;
    return {block, (local.z() * kB + local.y()) * kB + local.x()};
  }

 private:
  int span_, side_;
  Vec3i base_;
  std::vector<const WorkBlock*> table_;
};

class VoxelCorrector {
 public:
  explicit VoxelCorrector(const LevelContext& ctx) : ctx_(ctx), n_(ctx.neighborhoodSize), r_(n_ / 2) {
    for (int p = 0; p < 3; ++p) {
      TS_CHECK(ctx.planes[p]->pca.inputDimension == n_ * n_ * ctx.channels);
      query_[p].resize(std::size_t(ctx.planes[p]->pca.outputDimension));
    }
    buffer_.resize(std::size_t(n_) * n_ * ctx.channels);
  }

  // The corrected triple of voxel v (slot `slot` of `self`).
  CoordinateTriple correct(const BlockNeighborhood& around, const WorkBlock& self, int slot, const Vec3i& v) {
    const Mat3f& frame = self.frames[std::size_t(slot)];
    const int c = ctx_.channels;
    for (int p = 0; p < 3; ++p) {
      float* write = buffer_.data();
      for (int b = -r_; b <= r_; ++b)
        for (int a = -r_; a <= r_; ++a) {
          const auto [block, s] = around.at(v + roundVector(frame * planeOffset(p, a, b)));
          const float* color = block->colors.data() + std::size_t(s) * kMaxChannels;
          write = std::copy(color, color + c, write);
        }
      ctx_.planes[p]->pca.project(buffer_.data(), query_[p].data());
    }
    const CoordinateTriple current = self.triples[std::size_t(slot)];
    CoordinateTriple best = current;
    float bestDistance = distance(current, std::numeric_limits<float>::infinity());
    const CandidateTriples& candidates = *ctx_.triples;
    for (int p = 0; p < 3; ++p) {
      std::int32_t proposed[9];
      int proposals = 0;
      for (const auto& d : kOffsets) {
        const auto [block, s] = around.at(v + roundVector(frame * planeOffset(p, d[0], d[1])));
        const std::int32_t pixel = component(block->triples[std::size_t(s)], p);
        // [T_P(v + d) - h P(d)]: the in-plane offset is (a, b) in the plane's (u, v).
        const int u = wrapIndex(std::int64_t(pixel % ctx_.width) - ctx_.spacing * d[0], ctx_.width);
        const int w = wrapIndex(std::int64_t(pixel / ctx_.width) - ctx_.spacing * d[1], ctx_.height);
        const std::int32_t source = w * ctx_.width + u;
        if (std::find(proposed, proposed + proposals, source) != proposed + proposals) continue;
        proposed[proposals++] = source;
        const CoordinateTriple* triples = candidates.at(Plane(p), source);
        const float* errors = candidates.errorsAt(Plane(p), source);
        for (int k = 0; k < candidates.count; ++k) {
          if (!std::isfinite(errors[k])) continue;
          const float dist = distance(triples[k], bestDistance);
          if (dist < bestDistance) bestDistance = dist, best = triples[k];
        }
      }
    }
    return best;
  }

 private:
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
  std::vector<float> buffer_, query_[3];
};

}  // namespace

std::int64_t correctStep(const LevelContext& ctx, const WorkSet& before, WorkSet& after, int s, int voxelClass) {
  const int radius = ctx.readRadius();
  std::vector<std::int64_t> counts(after.keys.size(), 0);
  parallelForChunks(0, std::int64_t(after.keys.size()), kBlocksPerChunk, [&](std::int64_t begin, std::int64_t end) {
    VoxelCorrector corrector(ctx);
    for (std::int64_t i = begin; i < end; ++i) {
      WorkBlock& out = after.blocks[std::size_t(i)];
      const WorkBlock* in = before.find(after.keys[std::size_t(i)]);
      TS_CHECK(in != nullptr);
      out = *in;
      const BlockNeighborhood around(before, blockIndex(after.keys[std::size_t(i)]), radius);
      for (int slot = 0; slot < kBlockVoxels; ++slot) {
        const Vec3i v = out.origin + Vec3i(slot % kB, slot / kB % kB, slot / (kB * kB));
        if (voxelClass >= 0 &&
            (wrapIndex(v.x(), s) | wrapIndex(v.y(), s) << 1 | wrapIndex(v.z(), s) << 2) != voxelClass)
          continue;
        const CoordinateTriple t = corrector.correct(around, *in, slot, v);
        out.triples[std::size_t(slot)] = t;
        ctx.color(t, out.colors.data() + std::size_t(slot) * kMaxChannels);
        ++counts[std::size_t(i)];
      }
    }
  });
  std::int64_t total = 0;
  for (std::int64_t c : counts) total += c;
  return total;
}

}  // namespace texsynth::lazy
