#pragma once
// Internal to src/surface: the unfolding walk behind resampleNeighborhoods
// (surface_neighborhoods.h). WalkMesh renumbers the mesh once per call for memory locality;
// NeighborhoodUnfolder flattens the triangles around one centre and fills its grid cells.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/mesh.h"
#include "texsynth/geometry/mesh_topology.h"
#include "texsynth/surface/surface_neighborhoods.h"

namespace texsynth::surface_detail {

// A triangle as the walk needs it: its corners, the triangle across each edge e (4 * neighbour +
// the neighbour's edge, -1 on a border) and where corner e + 2 lies relative to edge e: corner e +
// along * E + out * E turned a quarter (E = edge e).
struct TriangleRecord {
  std::array<std::int32_t, 3> v{}, across{};
  std::array<float, 3> along{}, out{};
};

// The mesh renumbered for the walk: triangles in Morton order of their centroids and vertices in
// order of first use, so that what a walk touches lies close in memory (retiled meshes come in
// no spatial order; this halves the time). Records, stamps and flat triangles use these numbers.
struct WalkMesh {
  std::vector<TriangleRecord> records;             // by walk triangle number
  std::vector<std::int32_t> triangleRank;          // mesh triangle -> walk number
  std::vector<std::int32_t> vertexRank, vertexOf;  // mesh vertex <-> walk number

  WalkMesh(const Mesh& mesh, const MeshTopology& topology);
};

struct UnfoldScratch;

class NeighborhoodUnfolder {
 public:
  NeighborhoodUnfolder(const Mesh& mesh, const MeshTopology& topology, const WalkMesh& walk,
                       std::span<const Vec3f> tangents, float spacing, int size)
      : mesh_(mesh),
        topology_(topology),
        walk_(walk),
        records_(walk.records),
        tangents_(tangents),
        invSpacing_(1.0f / spacing),
        radius_(size / 2),
        size_(size),
        limit_(float(size / 2) + 0.5f),
        buckets_(std::size_t(2.0f * limit_ * kBucketsPerCell) + 2) {}

  // Buckets of the walk's queue per cell of distance from the centre: triangles come out nearest
  // first to within 1/16 cell, in the order they were queued within a bucket.
  static constexpr float kBucketsPerCell = 16;

  // Fills `cells` (size * size) and appends the members of the neighbourhood centred on p.
  void run(std::int32_t p, std::span<NeighborhoodCell> cells, std::vector<NeighborhoodMember>& members) const;

 private:
  Vec3f x(std::int32_t v) const { return mesh_.positions[std::size_t(v)]; }
  const Vec3i& tri(std::int32_t t) const { return topology_.triangles()[std::size_t(t)]; }

  void seedFans(std::int32_t p, UnfoldScratch& s) const;
  bool collectFan(std::int32_t p, int k, UnfoldScratch& s) const;
  void layOutFan(std::int32_t p, const Vec3f& t, const Vec3f& b, bool closed, UnfoldScratch& s) const;
  void expand(std::size_t index, UnfoldScratch& s) const;
  void rasterize(std::span<NeighborhoodCell> cells, UnfoldScratch& s) const;
  void fillUncovered(std::int32_t p, std::span<NeighborhoodCell> cells, UnfoldScratch& s) const;

  const Mesh& mesh_;
  const MeshTopology& topology_;
  const WalkMesh& walk_;
  std::span<const TriangleRecord> records_;
  std::span<const Vec3f> tangents_;
  float invSpacing_;
  int radius_, size_;
  float limit_;  // the square |dx|, |dy| <= limit_ the walk covers and members lie in
  std::size_t buckets_;
};

}  // namespace texsynth::surface_detail
