#pragma once
// Connectivity of a triangle mesh: the triangle across each edge, the triangles around each
// vertex in rotation order, border edges and vertices. Building it validates the mesh for
// algorithms that walk the surface (retiling, the surface synthesizer's neighbourhoods):
// every edge has one or two faces, and faces that share an edge agree on orientation.
//
// Conventions: edge e of triangle t joins its corners e and (e + 1) % 3. A vertex's triangles
// are listed fan by fan; a fan is a maximal run of triangles joined across edges at the vertex,
// listed counter-clockwise about the faces' normal (each next triangle is the one across the
// previous one's edge entering the vertex). A manifold vertex has one fan; a "bow tie" vertex
// where separate fans touch has several. Fans start at a border where they have one, else at
// their lowest triangle index, and come in order of their lowest triangle index.
#include <span>
#include <string>
#include <vector>

#include "texsynth/core/mesh.h"

namespace texsynth {

class MeshTopology {
 public:
  // Throws InputError(source, ...) with one sentence naming the first offending element for:
  // no vertices or no faces, an index out of range or a non-finite coordinate (Mesh::validate),
  // a face that repeats a vertex or has zero area ("face 12 is degenerate (zero area)"), an
  // edge shared by more than two faces ("non-manifold edge between vertices 4 and 9 (3 faces)"),
  // and two faces that traverse an edge in the same direction (inconsistent orientation).
  // Vertices no face uses are allowed (no triangles around them). Deterministic, parallel.
  MeshTopology(const Mesh& mesh, const std::string& source);

  int vertexCount() const { return int(ringOffsets_.size()) - 1; }
  int triangleCount() const { return int(triangles_.size()); }
  const std::vector<Vec3i>& triangles() const { return triangles_; }

  // The triangle across edge e of triangle t, or -1 if that edge is on a border.
  int neighbor(int t, int e) const { return neighbors_[std::size_t(3 * t + e)]; }
  // Which edge of neighbor(t, e) is the shared one (it joins the same vertices the other way),
  // or -1 on a border.
  int neighborEdge(int t, int e) const { return neighborEdges_[std::size_t(3 * t + e)]; }
  bool isBorderEdge(int t, int e) const { return neighbor(t, e) < 0; }
  // The corner (0, 1, 2) of triangle t at vertex v, or -1 if t does not use v.
  int cornerOf(int t, int v) const;

  // The triangles around vertex v, fan after fan (see the conventions above).
  std::span<const int> trianglesAround(int v) const;
  // The number of fans around v: 0 for a vertex no face uses, 1 for a manifold vertex.
  int fanCount(int v) const { return fanOffsets_[std::size_t(v) + 1] - fanOffsets_[std::size_t(v)]; }
  // Fan k (0 <= k < fanCount(v)) of the triangles around v.
  std::span<const int> fan(int v, int k) const;

  // Whether some edge at v lies on a border (has one face only).
  bool isBorderVertex(int v) const { return border_[std::size_t(v)] != 0; }
  int borderEdgeCount() const { return borderEdges_; }
  // No border edges: every edge has exactly two faces.
  bool closed() const { return borderEdges_ == 0; }

 private:
  std::vector<Vec3i> triangles_;
  std::vector<int> neighbors_;               // 3 per triangle
  std::vector<signed char> neighborEdges_;   // 3 per triangle
  std::vector<int> ringOffsets_, ring_;      // CSR: triangles around each vertex
  std::vector<int> fanOffsets_, fanStarts_;  // CSR: per vertex, the ring_ position where each fan starts
  std::vector<unsigned char> border_;        // per vertex
  int borderEdges_ = 0;
};

// Whether `face` (indices into `positions`) spans no area (its cross product, in double, is 0):
// the test MeshTopology rejects degenerate faces with.
bool faceHasZeroArea(const std::vector<Vec3f>& positions, const Vec3i& face);

}  // namespace texsynth
