#pragma once
// What `surface` and `animate --mesh` share before synthesizing: the exemplar and its analyses,
// the mesh welded, its retiled hierarchy (cached), the orientation field and the prepared
// surface, with their timings in the report.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"
#include "texsynth/surface/surface_synthesis.h"

namespace texsynth::cli {

struct SurfaceSetupArgs {
  std::string exemplar, mesh, field, sketch, up;
  int vertices = 48000, levels = 3, iterations = kSurfaceIterations;
  bool levelsGiven = false;                     // --levels on the command line (else capped by the exemplar's size)
  bool bakes = false;                           // --bake: the mesh must have UVs (checked right after reading it)
  bool verticesGiven = false;                   // --vertices on the command line
  float featureWeight = kSurfaceFeatureWeight;  // surfaceAnalysisOptions
};

struct SurfaceSetup {
  Image exemplar;
  Mesh input;  // as read (UVs kept)
  TextureOptimizationOptions options;
  std::vector<ExemplarAnalysis> analyses;
  std::optional<PreparedSurface> surface;
  bool hierarchyCached = false;
};

// Reads, analyses, retiles and prepares, adding "exemplar", "mesh", "input", "*_seconds" and
// "hierarchy_cached" to `report`. Errors about the mesh name args.mesh.
SurfaceSetup setUpSurface(const SurfaceSetupArgs& args, const GlobalOptions& globals, nlohmann::json& report,
                          Progress& progress);

// Peak memory of a surface synthesis at `vertices` retiled vertices, measured with
// `/usr/bin/time -f %M` on the bunny (brick.pat, 2 threads): 210 MB at 48k vertices, 490 MB at
// 200k (retiling, neighborhoods of both sizes on every level, the solver's state), slope and
// base rounded up.
inline double surfaceSynthesisBytes(int vertices) {
  return 64.0 * 1024 * 1024 + double(vertices) * 4096.0;
}

// The mesh side's errors name the mesh file, not the library's "mesh".
template <typename Work>
auto namingMesh(const std::string& path, Work work) {
  try {
    return work();
  } catch (const InputError& e) {
    if (e.file() == "mesh") throw InputError(path, e.problem());
    throw;
  }
}

// One JSON entry per optimization step (level, neighborhood, iteration, energy, changed ...).
nlohmann::json historyJson(const std::vector<OptimizationIteration>& history);

}  // namespace texsynth::cli
