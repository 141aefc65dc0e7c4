// The demo's surface section: hierarchy, orientation and resampling, synthesis, render, score.
#include "demo_surface.h"

#include <chrono>
#include <sstream>

#include "cli_common.h"
#include "demo_pixel.h"
#include "texsynth/core/timing.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/geometry/mesh_hierarchy_cache.h"
#include "texsynth/io/image_io.h"
#include "texsynth/render/render_mesh.h"
#include "texsynth/render/view_up.h"
#include "texsynth/surface/surface_quality.h"
#include "texsynth/surface/surface_synthesis.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

// `texsynth surface`'s default: a few seconds on 2 cores, and the weave of the demo's burlap (about 16
// pixels a repeat) stays visible in the 384-pixel views (at 16000 vertices it blurs into blotches).
constexpr int kDemoVertices = 48000;

}  // namespace

json demoSurfaceSynthesis(const Mesh& mesh, const std::string& meshName, const Image& exemplar,
                          const std::string& exemplarName, std::uint64_t seed, const std::string& cacheDirectory,
                          const std::function<std::string(const std::string&)>& out) {
  json section;
  TextureOptimizationOptions options;
  options.seed = seed;
  auto start = std::chrono::steady_clock::now();
  std::vector<ExemplarAnalysis> analyses;
  for (const AnalysisOptions& analysisOptions : surfaceAnalysisOptions(exemplar, options))
    analyses.push_back(analyzeExemplarCached(exemplar, analysisOptions, cacheDirectory));
  section["analysis_seconds"] = secondsSince(start);

  MeshHierarchyOptions hierarchyOptions;
  hierarchyOptions.vertices = kDemoVertices;
  hierarchyOptions.levels = options.levels;
  MeshHierarchy hierarchy = buildMeshHierarchyCached(mesh, hierarchyOptions, meshName, cacheDirectory);
  section["hierarchy_seconds"] = hierarchy.seconds;
  const PreparedSurface surface = prepareSurface(std::move(hierarchy), {}, options.neighborhoodSizes);
  section["prepare_seconds"] = surface.seconds;
  const SurfaceSynthesisResult result = synthesizeSurface(analyses, surface, options);
  section["synthesis_seconds"] = result.seconds;
  double finestSteps = 0;
  int finestCount = 0;
  for (const OptimizationIteration& step : result.history)
    if (step.iteration > 0 && step.level + 1 == int(surface.levels.size())) finestSteps += step.seconds, ++finestCount;
  section["finest_step_seconds"] = finestCount ? finestSteps / finestCount : 0.0;
  section["vertices"] = json::array();
  for (const MeshLevel& level : surface.hierarchy.levels) section["vertices"].push_back(level.mesh.vertexCount());
  section["requested_vertices"] = kDemoVertices;
  section["mesh"] = meshName;
  section["exemplar"] = exemplarName;

  Mesh colored = surface.finestMesh();
  colored.colors = result.colors;
  const SurfaceQuality quality = evaluateSurface(exemplar, colored, surface.levels.back().tangents);
  section["coherence"] = quality.coherence;
  section["rotation_invariant_coherence"] = quality.rotationInvariant;
  section["histogram"] = quality.histogram;
  section["flatness"] = quality.flatness;
  section["completeness"] = quality.completeness;
  int optimized = 0, kept = 0;
  bool polished = false;
  for (const SurfaceRefinement& refinement : result.levels) {
    if (refinement.step == SurfaceRefinementStep::Polish) {
      polished = refinement.kept;
      continue;
    }
    ++optimized;
    kept += refinement.kept;
  }
  section["refined_levels_kept"] = kept;
  section["refined_levels"] = optimized;
  section["polish_kept"] = polished;

  RenderOptions render;
  render.width = render.height = 384;
  render.up = viewUpDirection(mesh);
  writeImage(out("surface_synthesis.png"),
             sideBySide({exemplar, renderViews(colored, nullptr, {{30.0f, 20.0f}, {210.0f, 20.0f}}, render)}, 8));
  return section;
}

std::string surfaceMarkdown(const json& surface) {
  std::ostringstream md;
  md << "## Synthesis on a surface\n\n![exemplar, two views](surface_synthesis.png)\n\n";
  md << "`texsynth surface " << surface["exemplar"].get<std::string>() << " --mesh "
     << surface["mesh"].get<std::string>() << " --vertices " << surface["requested_vertices"]
     << "`: the mesh retiled by CGAL into a hierarchy of " << surface["vertices"].dump()
     << " vertices, oriented by a smooth tangent field (the exemplar upright), and every vertex "
        "a continuous exemplar coordinate: coarse to fine, k-coherence synthesis as 2D `parallel` "
        "(random coherent patches, upsampling through the parent triangles, jitter, correction of "
        "every vertex's 5x5 flattened neighbourhood), then the E+M steps of 2D `optimize` on those "
        "coordinates (17x17 then 9x9 neighborhoods), both matching colors and the distance to the "
        "exemplar's distinctive colors (a feature channel that keeps thin features), whose result is "
        "kept unless it makes a level "
        "flat or loses the exemplar's distinctive colors (kept at "
     << surface["refined_levels_kept"] << " of " << surface["refined_levels"]
     << " levels here), and at the finest level a last correction pass without the usage term under the "
        "same rule ("
     << (surface["polish_kept"].get<bool>() ? "kept" : "refused") << " here).\n\n";
  md << "| stage | seconds |\n|---|---:|\n";
  md << "| mesh hierarchy (cached for the next run) | " << fixed3(surface["hierarchy_seconds"]) << " |\n";
  md << "| tangent field and resampled neighborhoods | " << fixed3(surface["prepare_seconds"]) << " |\n";
  md << "| synthesis | " << fixed3(surface["synthesis_seconds"]) << " |\n";
  md << "| one E+M step at the finest level (mean) | " << fixed3(surface["finest_step_seconds"]) << " |\n\n";
  md << "Surface coherence (each vertex's resampled 7x7 neighborhood against its nearest exemplar patch, "
        "`texsynth eval` units): "
     << fixed3(surface["coherence"]) << " (" << fixed3(surface["rotation_invariant_coherence"])
     << " with the best of 8 rotations and mirrors); completeness " << fixed3(surface["completeness"])
     << "; histogram distance " << fixed3(surface["histogram"]) << "; flatness " << fixed3(surface["flatness"])
     << " (the share of vertices flatter than the exemplar's flattest tenth of patches, minus 0.10: about 0 "
        "when the texture covers the whole model).\n\n";
  return md.str();
}

}  // namespace texsynth::cli
