// texsynth surface EXEMPLAR --mesh M -o out.ply|.glb: texture grown directly on a mesh's surface
// by discrete optimization (surface synthesis, Han et al.), as vertex colors of a retiled copy;
// or, with --apply-coords, another map of the same material through a stored synthesis.
#include <chrono>

#include "cli_common.h"
#include "mode_flags.h"
#include "number_checks.h"
#include "surface_args.h"
#include "surface_setup.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/core/timing.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/surface/surface_coordinates.h"
#include "texsynth/surface/surface_synthesis.h"

namespace texsynth::cli {

namespace {

using nlohmann::json;

// Flags only synthesis uses: --apply-coords looks a stored synthesis up, it synthesizes nothing.
const std::vector<ModeFlag> kSurfaceModeFlags = {
    {"--mesh", {"synthesis"}},       {"--vertices", {"synthesis"}},       {"--levels", {"synthesis"}},
    {"--iterations", {"synthesis"}}, {"--field", {"synthesis"}},          {"--sketch", {"synthesis"}},
    {"--up", {"synthesis"}},         {"--coords", {"synthesis"}},         {"--bake", {"synthesis"}},
    {"--bake-size", {"synthesis"}},  {"--feature-weight", {"synthesis"}},
};

// Every usage check, before any file is read.
void checkUsage(const CLI::App& parser, const SurfaceArgs& args) {
  const bool apply = !args.applyCoords.empty();
  rejectFlagsOutsideMode(parser, kSurfaceModeFlags, apply ? "--apply-coords" : "synthesis", "with --apply-coords");
  rejectFlagsOutsideMode(parser, {{"--render-size", {"--render"}}, {"--views", {"--render"}}},
                         args.render.empty() ? "" : "--render", "without --render");
  rejectFlagsOutsideMode(parser, {{"--bake-size", {"--bake"}}}, args.bake.empty() ? "" : "--bake", "without --bake");
  if (!apply && args.mesh.empty())
    throw ParameterError("--mesh", "is required: the mesh to texture (" + readableMeshExtensions() + ")");
  if (!args.up.empty() && (!args.field.empty() || !args.sketch.empty()))
    throw ParameterError("--up", "sets the default field's direction; with " +
                                     std::string(args.field.empty() ? "--sketch" : "--field") +
                                     " that field orients the texture: drop one");
  for (const std::string& out : args.outputs) {
    const std::string ext = fileExtension(out);
    if (ext != "ply" && ext != "obj" && ext != "glb" && ext != "gltf")
      throw ParameterError("--output", "'" + out + "' is not a mesh file name texsynth writes (.ply .obj .glb .gltf)");
  }
  for (const auto& [flag, path] : {std::pair{"--render", &args.render}, std::pair{"--bake", &args.bake}})
    if (!path->empty() && fileKind(*path) != FileKind::Image)
      throw ParameterError(flag, "'" + *path + "' is not an image file name (" + readableImageExtensions() + ")");
  // Only PLY keeps named float vertex properties.
  for (const auto& [flag, path] : {std::pair{"--coords", &args.coords}, std::pair{"--apply-coords", &args.applyCoords}})
    if (!path->empty() && fileExtension(*path) != "ply")
      throw ParameterError(flag, "'" + *path + "': source coordinates are stored only in PLY files (.ply)");
  if (apply && args.outputs.empty())
    throw ParameterError("--output", "give -o: the mesh with the colors of EXEMPLAR at the stored coordinates");
  if (args.outputs.empty() && args.render.empty() && args.coords.empty() && args.bake.empty())
    throw ParameterError("--output", "nothing to write: give -o (mesh), --render, --bake or --coords");
  if (!apply)
    requireMemory(surfaceSynthesisBytes(args.vertices), "--vertices", std::to_string(args.vertices) + " vertices");
  requireSurfaceOutputMemory(args);
}

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", s);
  return text;
}

void finish(const SurfaceArgs& args, const GlobalOptions& globals, json& report, const SurfaceResult& result,
            Progress& progress, const std::string& summary) {
  auto start = std::chrono::steady_clock::now();
  report["outputs"] = writeSurfaceOutputs(args, result, progress);
  report["outputs_seconds"] = secondsSince(start);
  takePeakResidentMiB();
  report["peak_rss_mib"] = processPeakResidentMiB();
  std::string files;
  for (const json& out : report["outputs"]) files += (files.empty() ? "" : ", ") + out["file"].get<std::string>();
  finishReport(globals, report, args.stats, summary + "; wrote " + files);
}

void runApplyCoords(const SurfaceArgs& args, const GlobalOptions& globals) {
  const auto start = std::chrono::steady_clock::now();
  const Image exemplar = readImage(args.exemplar);
  SurfaceResult result;
  result.colored = readMesh(args.applyCoords);
  result.sources = sourcesFromCoordinates(result.colored, exemplar.width, exemplar.height, args.applyCoords);
  result.colored.attributes.clear();
  result.colored.colors = colorsOfSources(exemplar, result.sources);
  result.exemplarWidth = exemplar.width, result.exemplarHeight = exemplar.height;
  json report = {{"exemplar", args.exemplar},
                 {"exemplar_size", {exemplar.width, exemplar.height}},
                 {"apply_coords", args.applyCoords},
                 {"vertices", {result.colored.vertexCount()}}};
  report["lookup_seconds"] = secondsSince(start);
  auto progress = makeProgress(globals);
  finish(args, globals, report, result, *progress,
         "applied " + args.applyCoords + " to " + std::to_string(result.colored.vertexCount()) + " vertices");
}

void runSurface(const CLI::App& parser, const SurfaceArgs& args, const GlobalOptions& globals) {
  checkUsage(parser, args);
  if (!args.applyCoords.empty()) return runApplyCoords(args, globals);
  const auto start = std::chrono::steady_clock::now();
  SurfaceSetupArgs setupArgs{args.exemplar,
                             args.mesh,
                             args.field,
                             args.sketch,
                             args.up,
                             args.vertices,
                             args.levels,
                             args.iterations,
                             parser.count("--levels") > 0,
                             !args.bake.empty(),
                             parser.count("--vertices") > 0,
                             args.featureWeight};
  json report;
  auto progress = makeProgress(globals);
  SurfaceSetup setup = setUpSurface(setupArgs, globals, report, *progress);
  const Image& exemplar = setup.exemplar;
  const Mesh& input = setup.input;
  const PreparedSurface& surface = *setup.surface;
  LapTimer timer;
  const SurfaceSynthesisResult synthesis = synthesizeSurface(setup.analyses, surface, setup.options, *progress);
  report["synthesis_seconds"] = timer.lap();

  SurfaceResult result;
  result.colored = surface.finestMesh();
  result.colored.attributes.clear();
  result.colored.colors = synthesis.colors;
  result.sources = synthesis.sources;
  result.exemplarWidth = exemplar.width, result.exemplarHeight = exemplar.height;
  result.uvMesh = &input;

  report["vertices"] = json::array();
  report["levels"] = json::array();
  for (const MeshLevel& level : surface.hierarchy.levels) {
    report["vertices"].push_back(level.mesh.vertexCount());
    report["levels"].push_back({{"vertices", level.mesh.vertexCount()},
                                {"triangles", level.mesh.triangleCount()},
                                {"spacing", level.spacing}});
  }
  report["first_level"] = synthesis.firstLevel;
  report["steps"] = historyJson(synthesis.history);
  // Per refinement (E+M or polish) of a level: the measures before it and of its result, and which was kept.
  report["refinement"] = json::array();
  for (const SurfaceRefinement& r : synthesis.levels)
    report["refinement"].push_back({{"level", r.level},
                                    {"step", r.step == SurfaceRefinementStep::Polish ? "polish" : "optimization"},
                                    {"start_flatness", r.start.flatness},
                                    {"start_histogram", r.start.histogram},
                                    {"start_distinctive", r.start.distinctive},
                                    {"start_coherence", r.start.coherence},
                                    {"refined_distinctive", r.refined.distinctive},
                                    {"refined_coherence", r.refined.coherence},
                                    {"refined_flatness", r.refined.flatness},
                                    {"refined_histogram", r.refined.histogram},
                                    {"kept", r.kept}});
  const std::string summary =
      "synthesized " + std::to_string(result.colored.vertexCount()) + " vertices in " + seconds(secondsSince(start)) +
      " (hierarchy " + seconds(report["hierarchy_seconds"].get<double>()) + (setup.hierarchyCached ? ", cached" : "") +
      "; synthesis " + seconds(report["synthesis_seconds"].get<double>()) + ")";
  finish(args, globals, report, result, *progress, summary);
}

// Where the library's parameters come from on `surface`'s command line.
ParameterSources surfaceParameterSources(const SurfaceArgs& args) {
  return {{"exemplar", fromFile(args.exemplar)},
          {"image", fromFile(args.exemplar)},
          {"channels", fromFile(args.exemplar)},
          {"similarCount", fromFile(args.exemplar)},  // too few pixels for the similarity sets
          {"vertices", fromFlag("--vertices")},
          {"levels", fromFlag("--levels")},
          {"levelCount", fromFlag("--levels")},
          {"iterations", fromFlag("--iterations")},
          {"guide", fromFlag("--up")},
          {"width", fromFlag("--render-size")},
          {"height", fromFlag("--render-size")},
          {"size", fromFlag("--bake-size")}};
}

}  // namespace

Command registerSurfaceCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "surface",
      "Grow a texture directly on a mesh's surface (surface texture synthesis by discrete optimization, Han et al.): "
      "the mesh is retiled to --vertices near-uniform vertices and every vertex copies one pixel of EXEMPLAR, chosen "
      "so that every neighborhood on the surface looks like a neighborhood of the exemplar: coarse to fine, a "
      "k-coherence synthesis as `image --method parallel` on the mesh hierarchy, refined by the paper's E+M steps "
      "and, at the finest level, a last correction pass, each where it keeps the texture (--stats: refinement). No UV "
      "seams, no stretching, no tiling.\n"
      "  Texture density: one exemplar pixel per vertex spacing, so --vertices sets the scale: a 128-pixel-wide "
      "exemplar spans 128 vertex spacings of the surface. More vertices: smaller features, more repetitions and a "
      "finer result, at about linear cost. Relief smaller than one vertex spacing (a scan's bumps) is smoothed out "
      "of the geometry the neighborhoods are laid out on, not out of the output.\n"
      "  Orientation: a direction field on the surface gives the exemplar's up direction (its rows run across it): by "
      "default a smooth field following world +Y (--up to choose another), or the rotation field of --field / "
      "--sketch (`texsynth field`).\n"
      "  Outputs: -o the retiled mesh with vertex colors (.ply .obj .glb .gltf, as often as needed); --render a "
      "picture (views around the model's up: --up if given, else automatic, see --up); --bake a texture map in the UV "
      "layout of --mesh (which must have UVs); --coords each vertex's exemplar coordinates, which --apply-coords "
      "later re-applies to another map of the same material (normal, roughness ...) without synthesizing.\n"
      "  Caching: the exemplar analysis and the retiled mesh hierarchy are cached (the directory `texsynth --help` "
      "names): the first run on a mesh spends seconds retiling it, later runs at the same --vertices and --levels "
      "start synthesizing at once.\n"
      "Example: texsynth surface brick.png --mesh bunny.off -o bunny.ply --render bunny.png");
  auto args = std::make_shared<SurfaceArgs>();
  inputFiles(sub->add_option("EXEMPLAR", args->exemplar,
                             "Exemplar image (with --apply-coords: another map of the "
                             "material the coordinates were synthesized from)"))
      ->required();
  inputFiles(sub->add_option("--mesh", args->mesh, "Mesh to texture (" + readableMeshExtensions() + ")"));
  outputFiles(sub->add_option("-o,--output", args->outputs,
                              "The retiled mesh with vertex colors (.ply .obj .glb .gltf); may be repeated"));
  sub->add_option("--vertices", args->vertices,
                  "Vertices of the retiled mesh: the texture's density (one exemplar pixel per vertex spacing)")
      ->capture_default_str()
      ->check(integerIn(64, 5000000));
  sub->add_option("--levels", args->levels,
                  "Levels of the mesh hierarchy and the exemplar's Gaussian stack, each 4x fewer vertices than the "
                  "next (default 3, as Han et al.; fewer for an exemplar too small for 3)")
      ->check(integerIn(1, 6));
  sub->add_option("--iterations", args->iterations,
                  "Most E+M iterations per neighborhood size (17, then 9) and level; stops early when no match "
                  "changes (paper: 1-3)")
      ->capture_default_str()
      ->check(integerIn(1, 20));
  sub->add_option("--feature-weight", args->featureWeight,
                  "Weight of the feature channel: the distance to the exemplar's distinctive colors (its cracks, "
                  "veins, mortar: the fifth farthest from its median color), matched beside the colors so thin "
                  "features survive (Lefebvre & Hoppe 2006); colors span 0..1; 0 = colors alone")
      ->capture_default_str()
      ->check(finiteIn(0, 10));
  auto* field = inputFiles(
      sub->add_option("--field", args->field,
                      "Rotation field (.tsfield from `texsynth field`) whose local x axis is the up direction"));
  inputFiles(sub->add_option("--sketch", args->sketch,
                             "Sketch curves (JSON, docs/sketch-format.md) to design the field from first, as "
                             "`texsynth field`; instead of --field"))
      ->excludes(field);
  sub->add_option("--up", args->up,
                  std::string("X,Y,Z: the world direction the default smooth field follows, i.e. the exemplar's up "
                              "(default 0,1,0), and the up of --render's views (default: ") +
                      kViewUpRule + "); not with --field or --sketch");
  outputFiles(sub->add_option("--render", args->render, "Render the result to this image"));
  sub->add_option("--render-size", args->renderSize, "With --render: pixel size of each view")
      ->capture_default_str()
      ->check(integerIn(16, 4096));
  sub->add_option("--views", args->views, "With --render: views side by side, evenly around the model")
      ->capture_default_str()
      ->check(integerIn(1, 4));
  outputFiles(sub->add_option("--bake", args->bake,
                              "Bake the colors into a texture in the UV layout of --mesh (needs UVs: OBJ vt, PLY s,t "
                              "or u,v), charts grown a few texels for mip-maps"));
  sub->add_option("--bake-size", args->bakeSize, "With --bake: texels per side")
      ->capture_default_str()
      ->check(integerIn(16, 16384));
  outputFiles(sub->add_option("--coords", args->coords,
                              "Also write the retiled mesh with each vertex's exemplar coordinates (PLY properties "
                              "source_u, source_v in [0, 1]) for --apply-coords"));
  inputFiles(sub->add_option("--apply-coords", args->applyCoords,
                             "Re-apply a stored synthesis (a --coords file) to EXEMPLAR, another map of the same "
                             "material at any resolution: no synthesis, just the lookup; needs -o"));
  outputFiles(sub->add_option("--stats", args->stats,
                              "Write timings (per stage and per optimization step) and vertex counts per level as "
                              "JSON here"));
  return {sub, [sub, args, &globals] { runSurface(*sub, *args, globals); }, surfaceParameterSources(*args),
          "--vertices, --render-size or --bake-size"};
}

}  // namespace texsynth::cli
