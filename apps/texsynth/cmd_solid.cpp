// texsynth solid EXEMPLAR --method tile-deform|tile-blend|lazy: a solid (3D) texture, shown on a
// mesh (colored copy, per-pixel render), as slices, or as a whole volume.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>

#include "mode_flags.h"
#include "number_checks.h"
#include "solid_args.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/core/timing.h"
#include "texsynth/geometry/mesh_cut.h"
#include "texsynth/geometry/surface_voxels.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "texsynth/gradient/gradient_solid_texture.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"
#include "texsynth/render/glyph_mesh.h"
#include "texsynth/render/render_mesh.h"
#include "texsynth/render/view_up.h"
#include "texsynth/solid/solid_consumers.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

StackAxes parseStack(const std::string& text) {
  if (text == "x") return StackAxes::X;
  if (text == "y") return StackAxes::Y;
  if (text == "z") return StackAxes::Z;
  return StackAxes::All;
}

// Checks every output name before any work, so a typo costs nothing.
void checkOutputs(const SolidArgs& args) {
  std::size_t imageOutputs = 0;
  for (const std::string& out : args.outputs) {
    std::string ext = fileExtension(out);
    bool meshOut = ext == "ply" || ext == "obj" || ext == "glb" || ext == "gltf";
    bool volumeOut = ext == "nrrd" || ext == "vdb";
    if (ext == kGradientSolidExtension) {
      if (args.method != "gradient" || fileExtension(args.exemplars.front()) == kGradientSolidExtension)
        throw ParameterError("--output", "'" + out + "': a gradient solid (.tsgs) is written by --method gradient");
      continue;
    }
    if (meshOut && args.mesh.empty()) throw ParameterError("--output", "'" + out + "' is a mesh: give --mesh");
    if (fileKind(out) == FileKind::Image)
      ++imageOutputs;
    else if (!meshOut && !volumeOut)
      throw ParameterError("--output", "'" + out +
                                           "': unknown output type (.ply .obj .glb .gltf mesh, .png .jpg .exr "
                                           "slice, .nrrd .vdb volume, .tsgs gradient solid)");
  }
  if (imageOutputs != args.slices.size())
    throw ParameterError("--slice", std::to_string(args.slices.size()) + " slice(s) but " +
                                        std::to_string(imageOutputs) +
                                        " image output(s): give one -o image per --slice, in order");
  if (!args.render.empty() && args.mesh.empty()) throw ParameterError("--render", "needs --mesh");
  if (!args.cut.empty() && args.render.empty())
    throw ParameterError("--cut", "is a view of --render: give --render too");
  if (args.surface > 0 && args.mesh.empty()) throw ParameterError("--surface", "needs --mesh");
  if (args.outputs.empty() && args.render.empty() && args.surface == 0)
    throw ParameterError("--output", "nothing to write: give -o (mesh, slice or volume), --render or --surface");
}

// Refuses, before any synthesis, volumes and renders too big for this machine. Peak bytes per voxel, measured with
// `/usr/bin/time -f %M` and rounded up: a lazy volume keeps its pyramid's block caches (0.8 GB at 128³, 3.6 GB at 256³,
// README), the others the float volume and its encoding.
void requireSolidMemory(const SolidArgs& args, const Box3f& box) {
  const bool volume = std::any_of(args.outputs.begin(), args.outputs.end(), [](const std::string& out) {
    const std::string ext = fileExtension(out);
    return ext == "nrrd" || ext == "vdb";
  });
  if (volume) {
    double voxels = 1;
    for (int a = 0; a < 3; ++a)
      voxels *= std::max(1.0, std::ceil(double(args.resolution) * box.size()[a] / box.size().maxCoeff()));
    requireMemory(voxels * (args.method == "lazy" ? 400.0 : 32.0), "--resolution",
                  "a volume of " + std::to_string(std::int64_t(voxels)) + " voxels");
  }
  // A lazy slice synthesizes a slab around it at every level: 1.9 GB for a 512x506 cut through the bunny (README).
  if (args.method == "lazy" && !args.slices.empty())
    requireMemory(double(args.resolution) * args.resolution * 8000.0, "--resolution",
                  "lazy slices of " + std::to_string(args.resolution) + "x" + std::to_string(args.resolution));
  if (!args.render.empty()) {
    RenderOptions options;
    options.width = options.height = args.renderSize;
    requireMemory(renderMemoryBytes(options, args.views + (args.cut.empty() ? 0 : 1)), "--render-size",
                  "the rendered views");
  }
}

std::unique_ptr<SolidTexture> makeSolid(const SolidArgs& args, const Mesh& mesh, const Box3f& box, std::uint64_t seed,
                                        const GlobalOptions& globals, json& report, SolidBuild& build,
                                        std::shared_ptr<const GradientSolid>& gradient, Progress& synthesisProgress) {
  const std::string& exemplar = args.exemplars.front();
  if (args.method == "gradient") {  // a finished gradient solid or one synthesized now, spanning the box
    const bool file = fileExtension(exemplar) == kGradientSolidExtension;
    auto solid = file ? std::make_shared<const GradientSolid>(readGradientSolid(exemplar))
                      : synthesizeGradient(args, mesh, box, seed, globals, report);
    gradient = solid;
    GradientSolidTextureOptions options;
    options.placement = gradientSolidPlacement(*solid, box);
    options.detail = args.detail == "on";
    options.seed = seed;
    // Blend across a region boundary over one output sample, so edges are smooth but never soft.
    options.antialiasVoxels = std::min(1.0f, float(solid->voxels.maxCoeff()) / float(args.resolution));
    if (file) report["variant"] = "gradient solid";
    report["gradient_solid"] = {{"voxels", {solid->voxels.x(), solid->voxels.y(), solid->voxels.z()}},
                                {"spacing", solid->spacing},
                                {"regions", solid->hasRegions()},
                                {"detail", solid->hasDetail() && options.detail}};
    return makeGradientSolidTexture(std::move(solid), options);
  }
  // How many exemplars is a usage question (exit 2), asked before any file is read.
  if (args.exemplars.size() == 2)
    throw ParameterError("EXEMPLAR", "give one exemplar for all three planes, or three: XY YZ ZX");
  if (args.exemplars.size() == 3 && args.method != "lazy")
    throw ParameterError("EXEMPLAR", "only --method lazy takes three exemplars (XY YZ ZX)");
  SolidRecipe recipe;
  recipe.method = parseSolidMethod(args.method);
  if (fileKind(exemplar) == FileKind::Volume) {
    if (args.exemplars.size() > 1) throw ParameterError("EXEMPLAR", "give one exemplar volume");
    recipe.volume = readVolume(exemplar);
  } else {
    recipe.exemplars = readImages(args.exemplars);
  }
  recipe.box = box;
  recipe.tiles = args.tiles;
  recipe.seed = seed;
  recipe.tileBlend.tileSize = args.tileSize;
  recipe.tileBlend.weightExponent = args.blendExponent;
  recipe.tileBlend.blendSharpness = args.sharpness;
  TileDeformSolidOptions& deform = recipe.tileDeform;
  deform.deformation.cellSize = parseFloatTriple(args.cell, "--cell", true);  // 0 on an axis: a quarter of the exemplar
  deform.deformation.lambda = parseFloatTriple(args.lambda, "--lambda", true);
  deform.deformation.clamp = args.clamp;
  deform.deformation.noiseScale = args.noiseScale;
  deform.stacking = parseStack(args.stack);
  deform.blendSharpness = args.sharpness;
  if (recipe.method == SolidMethod::Lazy) fillLazyRecipe(args, mesh, recipe, report);
  build = buildSolid(recipe, synthesisProgress);
  if (!report.contains("variant")) report["variant"] = build.variant;
  if (!build.lazyParts.empty()) report["coarsest_level"]["seconds"] = build.coarsestSeconds;
  return std::move(build.texture);
}

// Which methods use each method-specific flag.
const std::vector<ModeFlag> kSolidModeFlags = {
    {"--stack", {"tile-deform"}},
    {"--cell", {"tile-deform"}},
    {"--lambda", {"tile-deform"}},
    {"--clamp", {"tile-deform"}},
    {"--noise-scale", {"tile-deform"}},
    {"--sharpness", {"tile-deform", "tile-blend"}},
    {"--tile-size", {"tile-blend"}},
    {"--blend-exponent", {"tile-blend"}},
    {"--field", {"lazy", "gradient"}},
    {"--sketch", {"lazy", "gradient"}},
    {"--mask", {"lazy", "gradient"}},
    {"--inner", {"lazy", "gradient"}},
    {"--shell", {"lazy", "gradient"}},
    {"--iterations", {"gradient"}},
    {"--check-points", {"gradient"}},
    {"--slices", {"gradient"}},
    {"--crossbar", {"gradient"}},
    {"--regions", {"gradient"}},
    {"--optimize", {"gradient"}},
    {"--clusters", {"gradient"}},
    {"--levels", {"lazy"}},
    {"--passes", {"lazy"}},
    {"--coarsest-passes", {"lazy"}},
    {"--dual-grid", {"lazy"}},
    {"--grid-cell", {"lazy"}},
    {"--subpasses", {"lazy"}},
    {"--candidates", {"lazy"}},
    {"--color-rule", {"lazy"}},
    {"--tiles", {"tile-deform", "tile-blend", "lazy"}},
    {"--detail", {"gradient", "gradient-file"}},
};

// Where the library's parameters come from on `solid`'s command line.
ParameterSources solidParameterSources(const SolidArgs& args) {
  return {{"exemplar", fromFiles(args.exemplars)},
          {"exemplars", fromFiles(args.exemplars)},
          {"exemplarCount", fromFlag("EXEMPLAR")},
          {"featureMask", fromFiles(args.masks)},
          {"masks", fromFiles(args.masks)},
          {"maskCount", fromFlag("--mask")},
          {"bounds", fromFile(args.mesh)},
          {"box", fromFile(args.mesh)},
          {"mesh", fromFile(args.mesh)},
          {"tiles", fromFlag("--tiles")},
          {"points", fromFlag("--tiles")},  // the mesh spans --tiles exemplars: too many leave lazy's range
          {"voxels", fromFlag("--tiles")},
          {"resolution", fromFlag("--resolution")},
          {"axis", fromFlag("--slice")},
          {"position", fromFlag("--slice")},
          {"cutAxis", fromFlag("--cut")},
          {"cutPosition", fromFlag("--cut")},
          {"width", fromFlag("--render-size")},
          {"height", fromFlag("--render-size")},
          {"blendSharpness", fromFlag("--sharpness")},
          {"deformation.cellSize", fromFlag("--cell")},
          {"deformation.lambda", fromFlag("--lambda")},
          {"deformation.clamp", fromFlag("--clamp")},
          {"deformation.noiseScale", fromFlag("--noise-scale")},
          {"tileSize", fromFlag("--tile-size")},
          {"weightExponent", fromFlag("--blend-exponent")},
          {"levels", fromFlag("--levels")},
          {"passes", fromFlag("--passes")},
          {"coarsestPasses", fromFlag("--coarsest-passes")},
          {"gridCellSize", fromFlag("--grid-cell")},
          {"subpassGrid", fromFlag("--subpasses")},
          {"candidateCount", fromFlag("--candidates")},
          {"depth", fromFlag("--shell")},
          {"inner", fromFlag("--inner")},
          {"method", fromFlag("--method")}};
}

void runSolid(const CLI::App& parser, SolidArgs& args, const GlobalOptions& globals) {
  // A .tsgs input is a finished gradient solid: it has no synthesis method to choose.
  if (fileExtension(args.exemplars.front()) == kGradientSolidExtension) {
    if (parser.count("--method") > 0)
      throw ParameterError("--method", "'" + args.exemplars.front() + "' is a finished gradient solid: drop --method");
    if (args.exemplars.size() > 1) throw ParameterError("EXEMPLAR", "give one .tsgs gradient solid");
    args.method = "gradient";
  }
  const bool gradientFile = fileExtension(args.exemplars.front()) == kGradientSolidExtension;
  rejectFlagsOutsideMode(parser, kSolidModeFlags, gradientFile ? "gradient-file" : args.method,
                         gradientFile ? "with a gradient solid (.tsgs)" : "with --method " + args.method);
  rejectFlagsOutsideMode(parser, {{"--render-size", {"--render"}}, {"--views", {"--render"}}, {"--up", {"--render"}}},
                         args.render.empty() ? "" : "--render", "without --render");
  if (!args.up.empty()) parseDirection(args.up, "--up");
  rejectFlagsOutsideMode(parser, {{"--shell", {"--inner"}}}, args.inner.empty() ? "" : "--inner", "without --inner");
  rejectFlagsOutsideMode(parser, {{"--grid-cell", {"--dual-grid"}}}, args.dualGrid ? "--dual-grid" : "",
                         "with --no-dual-grid");
  checkOutputs(args);
  std::vector<std::pair<int, float>> slices;
  for (const std::string& s : args.slices) slices.push_back(parseAxisPosition(s, "--slice", false));
  std::optional<std::pair<int, float>> cut;  // parsed before any work, so a typo costs nothing
  if (!args.cut.empty()) cut = parseAxisPosition(args.cut, "--cut", true);
  json report = {{"exemplar", args.exemplars}, {"method", args.method}, {"seed", globals.seed}};
  LapTimer timer;
  auto lap = [&timer] { return timer.lap(); };

  Mesh mesh;
  Box3f box;
  box.extend(Vec3f::Zero());
  box.extend(Vec3f::Ones());  // without a mesh, the unit cube
  if (!args.mesh.empty()) {
    mesh = readMesh(args.mesh);
    box = mesh.bounds();
  }
  requireSolidMemory(args, box);
  std::vector<Vec3f> surfacePoints;
  if (args.surface > 0) {
    surfacePoints = surfaceVoxelCenters(mesh, box, args.surface);
    // A lazy surface synthesizes the voxels its finer levels' corrections read: 1.7 GB at the peak for the bunny's
    // 825k surface voxels at 512 (bench/lazy_solid_cut.sh), about 2.1 KB each.
    requireMemory(double(surfacePoints.size()) * (args.method == "lazy" ? 2500.0 : 64.0), "--surface",
                  "the " + std::to_string(surfacePoints.size()) + " voxels of the surface");
  }
  SolidBuild lazy;  // what the factory built; its lazy parts for the statistics
  std::shared_ptr<const GradientSolid> gradient;
  // Synthesis on demand (the lazy method's levels) reports apart from the outputs' stage.
  auto synthesisProgress = makeProgress(globals);
  std::unique_ptr<SolidTexture> solid =
      makeSolid(args, mesh, box, globals.seed, globals, report, lazy, gradient, *synthesisProgress);
  report["setup_seconds"] = lap();
  report["setup_peak_rss_mib"] = takePeakResidentMiB();
  if (!lazy.lazyParts.empty())  // the work so far: the coarsest level over the box (separate from what follows)
    report["coarsest_level"]["lazy"] = lazyStats(lazy);
  if (args.surface > 0) {  // the whole surface at a resolution: synthesized and evaluated, for timing
    const std::vector<Vec3f>& points = surfacePoints;
    solid->prepare(points, *synthesisProgress);
    const double prepared = lap();
    solid->evaluateColors(points);
    report["surface"] = {{"resolution", args.surface},
                         {"voxels", points.size()},
                         {"synthesis_seconds", prepared},
                         {"lookup_seconds", lap()},
                         {"peak_rss_mib", takePeakResidentMiB()}};
    // What the surface cost per level, apart from the requests that follow (the totals are "lazy").
    if (!lazy.lazyParts.empty()) report["surface"]["lazy"] = lazyStats(lazy);
  }

  auto progress = makeProgress(globals);
  progress->begin("solid outputs", std::int64_t(args.outputs.size() + (args.render.empty() ? 0 : 1)));
  std::size_t nextSlice = 0;
  for (const std::string& out : args.outputs) {
    std::string ext = fileExtension(out);
    if (ext == kGradientSolidExtension) {
      writeGradientSolid(out, *gradient);
    } else if (fileKind(out) == FileKind::Image) {
      auto [axis, position] = slices[nextSlice++];
      writeImage(out, withPrepared(*solid, *synthesisProgress, [&](const SolidTexture& s) {
                   return sampleSlice(s, box, axis, position, args.resolution);
                 }));
    } else if (ext == "nrrd" || ext == "vdb") {
      VolumeWriteOptions volumeOptions;
      volumeOptions.floatSamples = args.floatVolume;
      writeVolume(out,
                  withPrepared(*solid, *synthesisProgress,
                               [&](const SolidTexture& s) { return sampleVolume(s, box, args.resolution); }),
                  volumeOptions);
    } else {
      Mesh colored = mesh;
      solid->prepare(colored.positions, *synthesisProgress);
      colorMeshVertices(colored, *solid);
      writeMesh(out, colored);
    }
    report["outputs"].push_back({{"file", out}, {"seconds", lap()}, {"peak_rss_mib", takePeakResidentMiB()}});
    if (!lazy.lazyParts.empty()) report["outputs"].back()["lazy"] = lazyStats(lazy);  // totals so far
    progress->advance(1);
  }
  if (!args.render.empty()) {
    RenderOptions options;
    options.width = options.height = args.renderSize;
    options.up = viewUp(args.up, mesh);
    std::vector<std::pair<float, float>> views;
    for (int v = 0; v < args.views; ++v) views.push_back({30.0f + 90.0f * v, 20.0f});
    SurfaceColorFunction colorAt = surfaceColorFunction(*solid);
    if (solid->preparesOnDemand())  // the renderer asks once per view for all visible points: prepare them first
      colorAt = [&solid, &synthesisProgress](const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals,
                                             std::vector<Vec3f>& colors) {
        solid->prepare(points, *synthesisProgress);
        colors = solid->evaluateColors(points, normals);
      };
    Image image = renderViews(mesh, &colorAt, views, options);
    if (cut) {  // the solid inside: a cap across the cut, coloured like the surface
      const auto [axis, fraction] = *cut;
      const MeshCut opened = cutOpenMesh(coloredCopy(mesh, options.defaultColor), axis, fraction,
                                         box.size().maxCoeff() / 512.0f, options.defaultColor);
      image = sideBySide(
          {image, renderViews(opened.mesh, &colorAt, {anglesAboutUp(options.up, cutViewAngles(axis))}, options)});
    }
    writeImage(args.render, image);
    report["outputs"].push_back({{"file", args.render}, {"seconds", lap()}});
    progress->advance(1);
  }
  progress->end();
  if (!lazy.lazyParts.empty()) report["lazy"] = lazyStats(lazy);
  takePeakResidentMiB();
  report["peak_rss_mib"] = processPeakResidentMiB();
  if (!args.stats.empty()) writeFileAtomically(args.stats, report.dump(2) + "\n");
  if (globals.json)
    printJsonWhenCommitted(report);
  else
    for (const auto& out : report["outputs"])
      sayWhenCommitted(globals, "wrote " + out["file"].get<std::string>() + " (" +
                                    std::to_string(out["seconds"].get<double>()) + " s)");
}

}  // namespace

Command registerSolidCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "solid",
      "Synthesize a solid (3D) texture and write it on a mesh, as slices or as a volume. Random access: any point is "
      "computed alone, so a mesh surface costs only its points.\n"
      "  tile-deform: tile the exemplar and deform a 3D grid with Perlin noise (Chen et al.). A volume exemplar "
      "(.nrrd .vdb) is tiled in 3D (method 1); a 2D exemplar is stacked along x, y or z, or along all three and "
      "blended by the surface normal, w_i = (n.i)^(2p) (method 2).\n"
      "  tile-blend: triplanar histogram-preserving tiling and blending (Heitz & Neyret 2018) of a 2D exemplar.\n"
      "  lazy: deterministic on-demand synthesis of coordinate triples (sketch-guided solid texturing), optionally "
      "following a rotation --field; only the voxels the outputs need are synthesized.\n"
      "  gradient: synthesize a whole gradient solid (a compact C1 tricubic solid, gradient-solid-textures §4) "
      "over the box at --resolution by optimizing its control points, optionally following --field and keeping "
      "--mask regions sharp; write it with -o SOLID.tsgs and view it with any other output. Structures a few "
      "voxels across come out well, thinner ones soft (docs/gradient-solids.md).\n"
      "Outputs: -o FILE, as often as needed; the extension says what: .ply .obj .glb .gltf a colored copy of "
      "--mesh, .png .jpg .exr the next --slice, .nrrd .vdb the volume over the mesh's box (or the unit cube) at "
      "--resolution, .tsgs the gradient solid of --method gradient.");
  auto args = std::make_shared<SolidArgs>();
  inputFiles(
      sub->add_option(
          "EXEMPLAR", args->exemplars,
          "2D exemplar image, or a 3D exemplar volume (.nrrd .vdb); lazy and gradient also take three: XY YZ ZX (the "
          "planes' exemplars). A gradient solid (.tsgs, from `texsynth vectorize`) is shown as it is, spanning the "
          "mesh's box (or the unit cube)"))
      ->required()
      ->expected(1, 3);
  sub->add_option("--method", args->method, "Synthesis method")
      ->capture_default_str()
      ->check(CLI::IsMember({"tile-deform", "tile-blend", "lazy", "gradient"}));
  inputFiles(sub->add_option("--mesh", args->mesh, "Mesh to texture (.obj .ply .off .stl)"));
  outputFiles(sub->add_option("-o,--output", args->outputs,
                              "Output file(s): colored mesh, slice image(s), volume or gradient solid (.tsgs)"));
  outputFiles(sub->add_option_function<std::string>(
      "--volume", [args](const std::string& file) { args->outputs.push_back(file); },
      "Write the volume (.nrrd or .vdb) at --resolution; the same as -o FILE"));
  sub->add_option("--slice", args->slices, "AXIS=POSITION in [0,1] across the box, e.g. z=0.5 (one image -o each)");
  sub->add_option("--resolution", args->resolution, "Voxels along the box's longest side, for slices and volumes")
      ->capture_default_str()
      ->check(integerIn(1, 4096));
  sub->add_option("--surface", args->surface,
                  "Synthesize the whole --mesh surface at this resolution (every voxel it passes through, voxels as "
                  "for --resolution) and report the time and voxel count in --stats / --json")
      ->check(integerIn(1, 4096));
  outputFiles(sub->add_option("--render", args->render,
                              "Render the textured --mesh (colors evaluated per pixel) to this image"));
  sub->add_option("--render-size", args->renderSize, "Size of each rendered view")
      ->capture_default_str()
      ->check(integerIn(16, 8192));
  sub->add_option("--views", args->views, "Rendered views side by side, 90 degrees apart")
      ->capture_default_str()
      ->check(integerIn(1, 4));
  sub->add_option("--up", args->up, "With --render: " + kViewUpHelp);
  sub->add_option("--tiles", args->tiles, "Exemplar tiles across the longest side of the box (texture scale)")
      ->capture_default_str()
      ->check(finiteIn(0.01, 1000));
  sub->add_flag("--float-volume", args->floatVolume, "Write .nrrd volumes as 32-bit floats instead of 8-bit");
  outputFiles(sub->add_option("--stats", args->stats, "Write timings and settings as JSON here"));
  sub->add_option("--stack", args->stack, "tile-deform with a 2D exemplar: stack along x, y, z or all three (xyz)")
      ->capture_default_str()
      ->check(CLI::IsMember({"x", "y", "z", "xyz"}));
  sub->add_option("--sharpness", args->sharpness,
                  "p of the normal blend w_i = (n.i)^(2p) (three-axis stacking, tile-blend)")
      ->capture_default_str()
      ->check(finiteIn(0.01, 64));
  sub->add_option("--cell", args->cell,
                  "tile-deform: grid cell size in exemplar pixels, S or SX,SY,SZ (0 = a quarter of the exemplar)")
      ->capture_default_str();
  sub->add_option("--lambda", args->lambda,
                  "tile-deform: noise factors L or LX,LY,LZ (0 on an axis: no deformation along it)")
      ->capture_default_str();
  sub->add_option("--clamp", args->clamp,
                  "tile-deform: largest displacement as a fraction of the cell (< 0.5, so cells never fold)")
      ->capture_default_str()
      ->check(finiteIn(0, 0.5, true));
  sub->add_option("--noise-scale", args->noiseScale, "tile-deform: grid cells per noise lattice spacing")
      ->capture_default_str()
      ->check(finiteIn(0.001, 1000));
  addTileBlendOptions(*sub, args->tileSize, args->blendExponent);
  auto* field = inputFiles(sub->add_option(
      "--field", args->field, "lazy, gradient: rotation field (.tsfield from `texsynth field`) the texture follows"));
  inputFiles(sub->add_option(
      "--inner", args->inner,
      "lazy, gradient with --mesh: exemplar for everything deeper than --shell below the surface (the paper's tree: "
      "bark outside, wood inside)"));
  sub->add_option(
         "--shell", args->shell,
         "lazy, gradient with --inner: depth of the outer region, as a fraction of the mesh's bounding-box diagonal")
      ->capture_default_str()
      ->check(finiteIn(1e-4, 1, true));
  sub->add_option("--levels", args->levels,
                  "lazy: pyramid levels L (default: 4, fewer for a small exemplar, so that the coarsest N x N "
                  "neighbourhood, 2^(L-1) pixels apart, fits in it)")
      ->check(integerIn(1, 8));
  sub->add_option("--passes", args->passes,
                  "lazy: correction passes per level above the coarsest (paper: 2); each widens what a request depends "
                  "on, so 1 answers a model in seconds")
      ->capture_default_str()
      ->check(integerIn(0, 8));
  sub->add_option("--coarsest-passes", args->coarsestPasses,
                  "lazy: correction passes at the coarsest level (paper: 3-5, cheap on its small grid)")
      ->capture_default_str()
      ->check(integerIn(0, 8));
  sub->add_flag("--dual-grid,!--no-dual-grid", args->dualGrid,
                "lazy: dual-grid correction (paper §5.3) on all levels but the coarsest: corrections read only their "
                "own MxMxM cell's current state, so a request depends on about 2 (M + N/sqrt 2) voxels per side "
                "and level whatever the passes and subpasses; the default, the standard scheme with --subpasses 1, "
                "depends on only passes x N/sqrt 2");
  sub->add_option("--grid-cell", args->gridCell,
                  "lazy with --dual-grid: the cell side M in voxels, even (paper: 10-15)")
      ->capture_default_str()
      ->check(integerIn(4, 32));
  sub->add_option("--subpasses", args->subpasses,
                  "lazy: s, each pass corrects the s^3 voxel classes (x, y, z mod s) in turn (paper: 2); 1 corrects "
                  "all voxels at once from the state before the pass")
      ->capture_default_str()
      ->check(integerIn(1, 2));
  sub->add_option("--candidates", args->candidates,
                  "lazy: N_T, candidate triples per exemplar pixel (paper: 12); fewer is faster")
      ->capture_default_str()
      ->check(integerIn(1, 64));
  sub->add_option("--color-rule", args->colorRule,
                  "lazy: a voxel's colour from its three planes' exemplar pixels: medoid (the one closest to the other "
                  "two, a real exemplar colour: crisp) or mean (soft where the planes disagree)")
      ->capture_default_str()
      ->check(CLI::IsMember({"medoid", "mean"}));
  inputFiles(
      sub->add_option(
          "--sketch", args->sketch,
          "lazy, gradient with --mesh: design the rotation field from these sketch curves first (as `texsynth field`, "
          "docs/sketch-format.md); instead of --field"))
      ->excludes(field);
  inputFiles(
      sub->add_option(
          "--mask", args->masks,
          "lazy, gradient: feature mask image(s), bright on feature curves (e.g. brick joints): one for all planes or "
          "three (XY YZ ZX); matching adds the distance to the features as a channel; gradient also keeps the two "
          "sides apart with sharp boundaries (--no-regions: the mask only guides matching)"))
      ->expected(1, 3);
  sub->add_option("--iterations", args->iterations, "gradient: optimization iterations per level (N_O)")
      ->capture_default_str()
      ->check(integerIn(1, 20));
  sub->add_option("--check-points", args->checkPoints, "gradient: random check points per control cube (N_C)")
      ->capture_default_str()
      ->check(integerIn(1, 64));
  sub->add_option("--slices", args->matchedSlices,
                  "gradient: slices matched per check point: 3, or 2 (the x and y slices; for anisotropic exemplars)")
      ->capture_default_str()
      ->check(CLI::IsMember({2, 3}));
  sub->add_flag("--crossbar,!--no-crossbar", args->crossbar,
                "gradient: crossbar matching (on by default): E_y among the 20 patches whose crossbar agrees best "
                "with E_x, E_z among the 50 agreeing with both; --no-crossbar: independent searches");
  sub->add_flag("--regions,!--no-regions", args->regions,
                "gradient with --mask: separate the mask's two regions with sharp boundaries (on by default)");
  sub->add_flag("--optimize", args->optimize,
                "gradient: refine the control points against every synthesized voxel by the exact tricubic (eq. 3; "
                "slower)");
  sub->add_option("--clusters", args->clusters,
                  "gradient: colour clusters N_T; a voxel averages only its two most frequent")
      ->capture_default_str()
      ->check(integerIn(2, 64));
  sub->add_option("--detail", args->detail,
                  "gradient: fit the residual detail and add its deterministic grain (on) or not (off); with a .tsgs "
                  "input: add the grain it stores")
      ->capture_default_str()
      ->check(CLI::IsMember({"on", "off"}));
  sub->add_option("--cut", args->cut,
                  "With --render: add a view of the mesh cut open at AXIS=FRACTION of its box (the +AXIS side "
                  "removed), showing the solid inside");
  return {sub, [sub, args, &globals] { runSolid(*sub, *args, globals); }, solidParameterSources(*args),
          "--resolution, --surface or --render-size"};
}

}  // namespace texsynth::cli
