// Lazy solid synthesis, the steps that create a level's triples: initialization of the
// coarsest level by tiled candidate slabs (§4.1) and upsampling with the field (§4.2, eq. 3-4),
// each followed by L&H 2005 jitter.
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/random.h"
#include "texsynth/core/wrap.h"
#include "texsynth/solid/lazy_blocks.h"

namespace texsynth::lazy {
namespace {

Vec3i voxelAt(const WorkBlock& block, int slot) {
  return block.origin + Vec3i(slot % kB, slot / kB % kB, slot / (kB * kB));
}

// floor(x + 1/2) per component: the paper's [.], closest integer point.
Vec3i roundVector(const Vec3f& v) {
  return {int(std::floor(v.x() + 0.5f)), int(std::floor(v.y() + 0.5f)), int(std::floor(v.z() + 0.5f))};
}

// J(v) = floor(h r xi + 1/2) along the local axes, xi uniform in [-1, 1]^3 from (seed, v, level).
CoordinateTriple jitter(const LevelContext& ctx, const Vec3i& v, const CoordinateTriple& t) {
  const float amplitude = float(ctx.spacing) * ctx.options->jitter;
  if (amplitude < 0.5f) return t;  // floor(a xi + 1/2) = 0 for every xi
  const std::uint64_t id = latticeId(v.x(), v.y(), v.z());
  int d[3];
  for (int a = 0; a < 3; ++a) {
    const float xi =
        2.0f * uniform01(hashKey(ctx.options->seed, id, std::uint64_t(ctx.level), std::uint64_t(a))) - 1.0f;
    d[a] = int(std::floor(amplitude * xi + 0.5f));
  }
  return offsetTriple(t, ctx.width, ctx.height, d[0], d[1], d[2]);
}

}  // namespace

bool LevelContext::integrated() const {
  return orientation && *orientation && level < options->trilinearLevels;
}

int LevelContext::readRadius() const {
  const int r = neighborhoodSize / 2;
  const int rotated = orientation && *orientation ? int(std::ceil(float(r) * 1.41421356f)) : r;
  return std::max(rotated, 1) + (integrated() ? 1 : 0);
}

Mat3f LevelContext::frame(int atLevel, const Vec3i& v) const {
  if (!orientation || !*orientation) return Mat3f::Identity();
  const float f = float(1 << (levels - 1 - atLevel));  // finest voxels per voxel of atLevel
  const Vec3f position = (v.cast<float>() + Vec3f::Constant(0.5f)) * f;
  return (*orientation)(atLevel, position).normalized().toRotationMatrix();
}

void LevelContext::color(const CoordinateTriple& t, float* blockColors, int slot) const {
  const std::int32_t pixels[3] = {t.xy, t.yz, t.zx};
  for (int p = 0; p < 3; ++p) {
    const float* from = planes[p]->image.pixels.data() + std::size_t(pixels[p]) * channels;
    float* to = blockColors + colorIndex(p, slot, channels);
    for (int i = 0; i < channels; ++i) to[i] = from[i];
  }
}

Vec3i LevelContext::wrapCoarsest(const Vec3i& voxel) const {
  Vec3i wrapped;
  for (int a = 0; a < 3; ++a) wrapped[a] = torusMin[a] + wrapIndex(std::int64_t(voxel[a]) - torusMin[a], torusSize[a]);
  return wrapped;
}

Vec3i LevelContext::storedBlock(const Vec3i& block) const {
  if (level != 0) return block;
  return (wrapCoarsest(block * kB).array() / kB).matrix();
}

void initializeBlock(const LevelContext& ctx, WorkBlock& block) {
  const int n = ctx.neighborhoodSize, k = ctx.options->subpartSize, h = ctx.spacing;
  for (int slot = 0; slot < kBlockVoxels; ++slot) {
    const Vec3i v = voxelAt(block, slot);
    // T([q^-1 v]) about the centre of v's K^3 subpart, so the warp stays small inside each part.
    const Vec3i part(floorDiv(v.x(), k), floorDiv(v.y(), k), floorDiv(v.z(), k));
    const Vec3f centre = (part.cast<float>() + Vec3f::Constant(0.5f)) * float(k);
    const Mat3f frame = ctx.frame(ctx.level, v);
    const Vec3f local = frame.transpose() * (v.cast<float>() + Vec3f::Constant(0.5f) - centre);
    const Vec3i w = roundVector(centre + local - Vec3f::Constant(0.5f));
    // Slabs of I_xy, N thick, stacked along z; each (subpart, layer) shifted at random.
    const int layer = floorDiv(w.z(), n);
    const int t = w.z() - layer * n - n / 2;
    const std::uint64_t key = hashKey(ctx.options->seed, latticeId(part.x(), part.y(), part.z()),
                                      std::uint64_t(ctx.level), std::uint64_t(std::int64_t(layer)) + 3);
    const int ox = int(uniformBelow(key, std::uint32_t(ctx.width)));
    const int oy = int(uniformBelow(mix64(key), std::uint32_t(ctx.height)));
    const int px = wrapIndex(std::int64_t(h) * w.x() + ox, ctx.width);
    const int py = wrapIndex(std::int64_t(h) * w.y() + oy, ctx.height);
    const CoordinateTriple slab = slabTriple(*ctx.triples, Plane::XY, py * ctx.width + px, t, h);
    block.triples[std::size_t(slot)] = jitter(ctx, v, slab);
  }
}

void upsampleBlock(const LevelContext& ctx, const BlockCache& parents, WorkBlock& block, std::uint64_t voxels) {
  const float h = float(ctx.spacing);
  for (int slot = 0; slot < kBlockVoxels; ++slot) {
    if (!(voxels >> slot & 1)) continue;
    const Vec3i v = voxelAt(block, slot);
    const Vec3i p(floorDiv(v.x(), 2), floorDiv(v.y(), 2), floorDiv(v.z(), 2));
    const Vec3i stored = ctx.level == 1 ? ctx.wrapCoarsest(p) : p;
    const auto it = parents.find(blockOfVoxel(stored));
    const int parentSlot = voxelSlot(stored);
    TS_CHECK_MSG(it != parents.end() && (it->second.done >> parentSlot & 1),
                 "lazy synthesis planned a parent voxel that was not synthesized");
    const CoordinateTriple parent = it->second.triples[std::size_t(parentSlot)];
    // Eq. 3: t_v = h_l (delta - 1/2), delta = v mod 2 (children centred on the parent), taken
    // into the parent's local frame (q^-1 t_v) and added to its triple by eq. 4.
    const Vec3f offset = (v - 2 * p).cast<float>().array() * h - 0.5f * h;
    const Vec3i d = roundVector(ctx.frame(ctx.level - 1, p).transpose() * offset);
    const CoordinateTriple child = offsetTriple(parent, ctx.width, ctx.height, d.x(), d.y(), d.z());
    block.triples[std::size_t(slot)] = jitter(ctx, v, child);
  }
}

void finishBlock(const LevelContext& ctx, WorkBlock& block, std::uint64_t voxels) {
  for (int slot = 0; slot < kBlockVoxels; ++slot) {
    if (!(voxels >> slot & 1)) continue;
    block.frames[std::size_t(slot)] = ctx.frame(ctx.level, voxelAt(block, slot));
    ctx.color(block.triples[std::size_t(slot)], block.colors.data(), slot);
  }
}

}  // namespace texsynth::lazy
