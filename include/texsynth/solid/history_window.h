#pragma once
// History windows (sketch-guided solid texturing §5.2-5.3): for a voxel p being corrected, the
// version of every neighbour q in p's D x D x D window that the correction reads. Versions
// count a level's correction passes: 0 is the upsampled state, i the state after pass i.
// The standard schemes are special cases (a pass reads version i - 1 everywhere; subpass j of
// pass i reads version i of the classes already corrected in the pass, Fig. 6a-c); grid
// correction reads a neighbour's latest version only inside p's own M^3 cell and the phase's
// starting version elsewhere (Fig. 6d, 7); schemes combine by intersection, the element-wise
// minimum (§5.3.1: H_g ∩ H_s).
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/math.h"

namespace texsynth {

class HistoryWindow {
 public:
  // "The latest version of q": larger than any pass count, so intersecting with the subpass
  // window turns it into the version q has at that moment.
  static constexpr std::int8_t kLatest = 127;

  // Every offset within `radius` (per axis) at `version`. The paper's D = ceil(N sqrt 2) is the
  // side 2 radius + 1 that covers a rotated N x N neighbourhood (radius = ceil(N / sqrt 2)).
  HistoryWindow(int radius, std::int8_t version);

  int radius() const { return radius_; }
  int side() const { return 2 * radius_ + 1; }
  // Offset q - p, each component in [-radius, radius].
  std::int8_t at(const Vec3i& offset) const { return versions_[indexOf(offset)]; }
  void set(const Vec3i& offset, std::int8_t version) { versions_[indexOf(offset)] = version; }
  // Raw D^3 versions, x fastest (offset + radius).
  std::span<const std::int8_t> versions() const { return versions_; }

  // H ∩ other: the element-wise minimum (same radius). Never reads newer than either window.
  HistoryWindow& intersect(const HistoryWindow& other);
  friend HistoryWindow operator&(HistoryWindow a, const HistoryWindow& b) { return a.intersect(b); }
  bool operator==(const HistoryWindow& other) const = default;

  std::size_t indexOf(const Vec3i& offset) const {
    const int d = side();
    return std::size_t(((offset.z() + radius_) * d + (offset.y() + radius_)) * d + (offset.x() + radius_));
  }

 private:
  int radius_;
  std::vector<std::int8_t> versions_;
};

// The class of voxel v under s^3 subpasses: bits x mod s | (y mod s) << 1 | (z mod s) << 2
// (always 0 for s = 1).
int subpassClassOf(const Vec3i& v, int s);

// Pass `pass` (1-based) without subpasses: every neighbour at version pass - 1.
HistoryWindow passWindow(int radius, int pass);
// Subpass `subpass` (0-based) of pass `pass` for voxel `voxel`, the classes being corrected in
// `classOrder` (s^3 entries): a neighbour whose class comes earlier in the order was already
// corrected in this pass (version pass), the others not yet (pass - 1). The voxel's own class
// reads pass - 1: a step computes all its results before writing any.
HistoryWindow subpassWindow(int radius, int pass, int subpass, std::span<const int> classOrder, int s,
                            const Vec3i& voxel);
// Grid correction over cells [cM - shift, cM - shift + M) per axis: a neighbour in the voxel's
// own cell at kLatest, every other one at `startVersion` (the state the phase began from).
HistoryWindow gridWindow(int radius, int cellSize, int shift, int startVersion, const Vec3i& voxel);

}  // namespace texsynth
