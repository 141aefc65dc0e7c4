// The setup `surface` and `animate --mesh` share: exemplar analyses, retiled hierarchy, field,
// prepared surface.
#include "surface_setup.h"

#include <cmath>
#include <filesystem>

#include "texsynth/core/error.h"
#include "texsynth/core/mesh_weld.h"
#include "texsynth/core/timing.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/exemplar/gaussian_stack.h"
#include "texsynth/field/field_designer.h"
#include "texsynth/field/field_io.h"
#include "texsynth/field/sketch.h"
#include "texsynth/geometry/mesh_hierarchy_cache.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth::cli {

using nlohmann::json;

json historyJson(const std::vector<OptimizationIteration>& history) {
  json steps = json::array();
  for (const OptimizationIteration& h : history)
    steps.push_back({{"level", h.level},
                     {"neighborhood", h.neighborhoodSize},
                     {"iteration", h.iteration},
                     {"energy", h.energy},
                     {"changed", h.changedMatches},
                     {"neighborhoods", h.neighborhoods},
                     {"seconds", h.seconds}});
  return steps;
}

namespace {

// The levels must fit both the exemplar's Gaussian stack and the mesh hierarchy; a shortfall
// blames what the user typed (--levels alone, else --vertices).
void checkLevels(const SurfaceSetupArgs& args, const MeshHierarchyOptions& hierarchy, int stackLevels) {
  const std::string levels = std::to_string(hierarchy.levels);
  if (hierarchy.levels > stackLevels)
    throw ParameterError("--levels", levels + " is more than the " + std::to_string(stackLevels) +
                                         " levels the Gaussian stack of " + args.exemplar + " has");
  const int least = minimumFinestVertices(hierarchy.levels, hierarchy.ratio);
  if (hierarchy.vertices >= least) return;
  const std::string problem = std::to_string(hierarchy.vertices) + " vertices leave the coarsest of " + levels +
                              " levels too few to retile: give at least " + std::to_string(least) +
                              " vertices, or fewer levels";
  throw ParameterError(args.levelsGiven && !args.verticesGiven ? "--levels" : "--vertices", problem);
}

}  // namespace

SurfaceSetup setUpSurface(const SurfaceSetupArgs& args, const GlobalOptions& globals, json& report,
                          Progress& progress) {
  LapTimer timer;
  SurfaceSetup setup;
  setup.exemplar = readImage(args.exemplar);
  TextureOptimizationOptions& options = setup.options;
  options.seed = globals.seed;
  // Without --levels, a small exemplar gets the levels its Gaussian stack has (as `image --method optimize`).
  const int stackLevels = defaultStackLevelCount(setup.exemplar.width, setup.exemplar.height);
  options.levels = args.levelsGiven ? args.levels : std::min(args.levels, stackLevels);
  options.maxIterations = args.iterations;
  MeshHierarchyOptions hierarchyOptions;
  hierarchyOptions.vertices = args.vertices;
  hierarchyOptions.levels = options.levels;
  checkLevels(args, hierarchyOptions, stackLevels);  // before the mesh is read or anything analysed
  setup.input = readMesh(args.mesh);
  if (args.bakes && !setup.input.attributes.count(kUvAttribute))
    throw ParameterError("--bake", "'" + args.mesh +
                                       "' has no texture coordinates (UVs) to bake into; give a mesh with them "
                                       "(OBJ vt, PLY s,t or u,v) or drop --bake");
  // UV and normal seams store a vertex once per side; synthesis must see one surface across them.
  const WeldedMesh welded = weldCoincidentVertices(setup.input);
  if (welded.mesh.triangles.empty()) throw InputError(args.mesh, "every face has coinciding corners (zero area)");

  SurfaceOrientation orientation;
  if (!args.up.empty()) orientation.smooth.guide = parseDirection(args.up, "--up");

  report["exemplar"] = args.exemplar;
  report["exemplar_size"] = {setup.exemplar.width, setup.exemplar.height};
  report["mesh"] = args.mesh;
  report["seed"] = globals.seed;
  report["input"] = {{"vertices", setup.input.vertexCount()},
                     {"triangles", setup.input.triangleCount()},
                     {"welded_vertices", welded.mesh.vertexCount()}};
  report["read_seconds"] = timer.lap();
  const std::string cache = defaultCacheDirectory();
  report["feature_weight"] = args.featureWeight;
  for (const AnalysisOptions& analysisOptions : surfaceAnalysisOptions(setup.exemplar, options, args.featureWeight))
    setup.analyses.push_back(analyzeExemplarCached(setup.exemplar, analysisOptions, cache, progress));
  report["analysis_seconds"] = timer.lap();

  setup.hierarchyCached =
      std::filesystem::exists(meshHierarchyCachePath(cache, meshHierarchyCacheKey(welded.mesh, hierarchyOptions)));
  MeshHierarchy hierarchy = namingMesh(
      args.mesh, [&] { return buildMeshHierarchyCached(welded.mesh, hierarchyOptions, args.mesh, cache, progress); });
  report["hierarchy_cached"] = setup.hierarchyCached;
  report["hierarchy_seconds"] = timer.lap();

  std::optional<RotationField> field;
  if (!args.field.empty()) field = readField(args.field).rotations;
  if (!args.sketch.empty())
    field = namingMesh(args.mesh, [&] {
              return designField(setup.input, readSketch(args.sketch), {}, progress, args.sketch);
            }).rotations;
  if (field) orientation.field = &*field;
  report["field_seconds"] = timer.lap();
  setup.surface = namingMesh(args.mesh, [&] {
    return prepareSurface(std::move(hierarchy), orientation, options.neighborhoodSizes, progress);
  });
  report["prepare_seconds"] = timer.lap();
  return setup;
}

}  // namespace texsynth::cli
