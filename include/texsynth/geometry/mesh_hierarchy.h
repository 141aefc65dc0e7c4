#pragma once
// The retiled mesh hierarchy of surface texture synthesis (Han et al., "Fast example-based
// surface texture synthesis via discrete optimization", section 2.3): the input surface retiled
// independently at a few resolutions about `ratio` apart in vertex count, each vertex knowing
// the triangle of the next coarser level it lies on, so a coarse result can be upsampled.
// mesh_hierarchy_cache.h keeps built hierarchies on disk.
#include <string>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/progress.h"

namespace texsynth {

struct MeshHierarchyOptions {
  int vertices = 48000;  // the finest level's vertex count, in [1, 50000000]
  int levels = 3;        // >= 1; the coarsest level gets vertices / ratio^(levels - 1) (at least 32)
  float ratio = 4.0f;    // vertex-count ratio between adjacent levels, in (1, 64]
};

struct MeshLevel {
  Mesh mesh;          // retiled (retileMesh), with normals
  float spacing = 0;  // sqrt(surface area / vertex count): world length of one synthesis "pixel" at this level
  std::vector<int> parentTriangle;       // per vertex: the triangle of the next coarser level (levels[l-1])
                                         // nearest it; empty at level 0
  std::vector<Vec3f> parentBarycentric;  // per vertex: barycentric weights in that triangle (>= 0, sum 1)
};

struct MeshHierarchy {
  std::vector<MeshLevel> levels;  // [0] coarsest ... back() finest
  double seconds = 0;             // wall time of the build (of the cache lookup, when it hit)
};

// Retiles `input` at every level (in parallel, one retileMesh each), then finds each vertex's
// parent by the closest point on the coarser level (SurfaceProjector). Progress: a stage
// "retiling" advanced per finished level, then "parent triangles" per level. Throws
// InputError(source, ...) for a mesh MeshTopology rejects, ParameterError("vertices" |
// "levels" | "ratio", ...) for bad options. Deterministic, the same for any thread count.
MeshHierarchy buildMeshHierarchy(const Mesh& input, const MeshHierarchyOptions& options, const std::string& source,
                                 Progress& progress = noProgress());

// The fewest finest-level vertices that leave the coarsest of `levels` levels the 32 vertices a
// retiling needs (meshLevelVertexCounts refuses fewer). For checks before any work.
int minimumFinestVertices(int levels, float ratio);

// The target vertex count of every level, coarsest first (what buildMeshHierarchy asks
// retileMesh for). Throws ParameterError as buildMeshHierarchy.
std::vector<int> meshLevelVertexCounts(const MeshHierarchyOptions& options);

}  // namespace texsynth
