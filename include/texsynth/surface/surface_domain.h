#pragma once
// Flow animation on surfaces: one level's resampled neighborhoods as a domain of the discrete
// solver's steps (texsynth/image/discrete_steps.h), which repair each advected frame. (Static
// surface synthesis refines on continuous coordinates instead: surface_optimization.h.) Samples are vertices; a
// neighborhood reads its cells as convex combinations of vertex colors (x_p = W_p x), its members and coverings at
// their flattened offsets.
#include <cstdint>
#include <limits>

#include "texsynth/surface/surface_neighborhoods.h"

namespace texsynth::detail {

struct SurfaceDomain {
  const SurfaceNeighborhoods& neighborhoods;
  int channels = 3;

  std::int64_t sampleCount() const { return std::int64_t(neighborhoods.vertexCount()); }
  std::int64_t activeCount() const { return std::int64_t(neighborhoods.activeCount()); }
  std::int64_t sampleChunk() const { return 1024; }
  std::int64_t activeChunk() const { return 16; }
  int size() const { return neighborhoods.size; }
  bool masksCells() const { return true; }

  template <class ColorOf>
  void gather(std::int64_t a, ColorOf&& colorOf, float* out) const {
    for (const NeighborhoodCell& cell : neighborhoods.cellsOf(std::size_t(a))) {
      if (!cell.covered) {
        *out = std::numeric_limits<float>::quiet_NaN();
        out += channels;
        continue;
      }
      const float* c0 = colorOf(cell.vertex[0]);
      const float* c1 = colorOf(cell.vertex[1]);
      const float* c2 = colorOf(cell.vertex[2]);
      const float w0 = cell.weight[0], w1 = cell.weight[1], w2 = cell.weight[2];
      for (int k = 0; k < channels; ++k) *out++ = w0 * c0[k] + w1 * c1[k] + w2 * c2[k];
    }
  }

  template <class Visit>
  void forEachMember(std::int64_t a, Visit&& visit) const {
    for (const NeighborhoodMember& member : neighborhoods.membersOf(std::size_t(a)))
      visit(std::int64_t(member.vertex), member.dx, member.dy);
  }

  template <class Visit>
  void forEachCovering(std::int64_t vertex, Visit&& visit) const {
    for (const CoveringEntry& entry : neighborhoods.coveringOf(std::size_t(vertex)))
      visit(std::int64_t(entry.neighborhood), entry.dx, entry.dy);
  }
};

}  // namespace texsynth::detail
