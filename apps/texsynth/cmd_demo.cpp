// texsynth demo: a tour on built-in defaults. Analyses a real exemplar (GIMP's pink marble from
// gimp-data), renders a real mesh (CGAL's bunny from libcgal-demo), synthesizes 2D textures and
// scores them against the plain-tiling baseline (demo_pixel.cpp), vectorizes and edits a small gradient solid
// (demo_gradient.cpp), and writes a short report with pictures. Falls back to built-in procedural data when those
// packages are absent.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_common.h"
#include "demo_animation.h"
#include "demo_fallbacks.h"
#include "demo_gradient.h"
#include "demo_lazy.h"
#include "demo_pixel.h"
#include "demo_studio.h"
#include "demo_surface.h"
#include "image_layout.h"
#include "number_checks.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/core/output_batch.h"
#include "texsynth/core/timing.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"
#include "texsynth/render/render_mesh.h"
#include "texsynth/render/view_up.h"
#include "texsynth/solid/solid_consumers.h"
#include "texsynth/solid/tile_deform_solid.h"

namespace texsynth::cli {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

struct DemoArgs {
  std::string outputDir = "texsynth-demo";
  std::string exemplar, mesh, cacheDir;
  int exemplarSize = 128;
  int renderSize = 512;
};

const char* kDefaultPattern = "Stone/pink_marble.pat";
const char* kDefaultMesh = "bunny00.off";
// The surface section's exemplar: a woven fabric shows orientation and seams on the mesh at a
// glance (the demo exemplar stands in where gimp-data is missing).
const char* kSurfacePattern = "Fabric/burlap.pat";

// The centre `size` x `size` crop (or the whole image if smaller), as RGB.
Image centerCrop(const Image& image, int size) {
  int w = std::min(size, image.width), h = std::min(size, image.height);
  return image.withChannels(3).crop((image.width - w) / 2, (image.height - h) / 2, w, h);
}

// A level's first three PCA coordinates as colours: what the matcher "sees" of each pixel.
Image pcaPicture(const ExemplarLevel& level) {
  Image picture(level.image.width, level.image.height, 3, 0.5f);
  int dims = std::min(3, level.pca.outputDimension);
  for (std::size_t p = 0; p < level.image.pixelCount(); ++p)
    for (int c = 0; c < dims; ++c) {
      float sigma = std::sqrt(std::max(level.pca.variances[c], 1e-12f));
      float v = 0.5f + 0.18f * level.projected[p * level.pca.outputDimension + c] / sigma;
      picture.pixels[p * 3 + c] = std::clamp(v, 0.0f, 1.0f);
    }
  return picture;
}

// Row 1: the Gaussian stack levels (coarsest first); row 2: their PCA pictures.
Image stackPicture(const ExemplarAnalysis& analysis) {
  std::vector<Image> stack, pca;
  for (const ExemplarLevel& level : analysis.levels) {
    stack.push_back(level.image.channelRange(0, analysis.colorChannels));
    pca.push_back(pcaPicture(level));
  }
  Image top = sideBySide(stack, 4), bottom = sideBySide(pca, 4);
  Image out(top.width, top.height + bottom.height, 3, 1.0f);
  pasteImage(out, top, 0, 0);
  pasteImage(out, bottom, 0, top.height);
  return out;
}

std::string markdownReport(const json& r) {
  std::ostringstream md;
  md << "# texsynth demo report\n\n";
  md << "## Exemplar\n\n![exemplar](exemplar.png)\n\n";
  md << "- source: `" << r["exemplar"]["source"].get<std::string>() << "`"
     << (r["exemplar"]["fallback"].get<bool>() ? " (built-in procedural fallback: gimp-data not installed)" : "")
     << "\n";
  md << "- analysed at " << r["exemplar"]["width"] << "x" << r["exemplar"]["height"] << " pixels\n\n";
  md << "## Exemplar analysis\n\n![Gaussian stack (top) and first three PCA coordinates "
        "(bottom)](gaussian_stack.png)\n\n";
  md << "Gaussian stack levels, coarsest first (top row), and each level's first three PCA coordinates as colours "
        "(bottom row). Neighborhoods "
     << r["analysis"]["neighborhood"] << "x" << r["analysis"]["neighborhood"] << ", k = " << r["analysis"]["k"]
     << " similar neighborhoods per pixel. Analysis took " << fixed3(r["analysis"]["seconds"]) << " s"
     << (r["analysis"]["cached"].get<bool>() ? " (loaded from the cache)" : "") << ".\n\n";
  md << "| level | spacing h | PCA dims | kept energy |\n|---:|---:|---:|---:|\n";
  for (const auto& level : r["analysis"]["levels"])
    md << "| " << level["level"] << " | " << level["spacing"] << " | " << level["dimensions"] << " | "
       << fixed3(level["kept_energy"]) << " |\n";
  md << "\n## Mesh\n\n![mesh](mesh.png)\n\n![solid texture](mesh_solid.png)\n\n";
  md << "- source: `" << r["mesh"]["source"].get<std::string>() << "`"
     << (r["mesh"]["fallback"].get<bool>() ? " (built-in sphere: libcgal-demo meshes not extracted)" : "") << ", "
     << r["mesh"]["vertices"] << " vertices, " << r["mesh"]["triangles"] << " triangles\n";
  md << "- rendered in " << fixed3(r["mesh"]["render_seconds"]) << " s (two views). The second picture is a solid "
     << "texture synthesized from the exemplar by tiling and deformation (stacked along x, y and z, blended by the "
     << "normal), evaluated at every pixel: " << fixed3(r["mesh"]["solid_render_seconds"]) << " s.\n\n";
  md << pixelMarkdown(r["pixel"], r["tiling_baseline"]);
  md << surfaceMarkdown(r["surface"]);
  md << animationMarkdown(r["animation"]);
  md << lazySolidMarkdown(r["lazy_solid"]);
  md << studioMarkdown(r["studio"]);
  md << gradientMarkdown(r["gradient"]);
  return md.str();
}

void runDemo(const DemoArgs& args, const GlobalOptions& globals) {
  RenderOptions render;
  render.width = render.height = args.renderSize;
  const std::vector<std::pair<float, float>> views = {{30.0f, 20.0f}, {-60.0f, 15.0f}};
  requireMemory(renderMemoryBytes(render, int(views.size())), "--render-size", "the rendered views");
  std::error_code ec;
  if (fs::exists(args.outputDir, ec) && !fs::is_directory(args.outputDir, ec))
    throw OutputError(args.outputDir, "exists and is not a directory");
  // Created through the run's batch: removed again, with everything staged in it, if the demo fails.
  createOutputDirectories(args.outputDir);
  auto progress = makeProgress(globals);
  auto out = [&](const std::string& name) { return (fs::path(args.outputDir) / name).string(); };
  json report;

  // Exemplar: the user's, else GIMP's marble, else a procedural one.
  std::string exemplarPath = args.exemplar;
  if (exemplarPath.empty()) exemplarPath = gimpPattern(kDefaultPattern).value_or("");
  bool exemplarFallback = exemplarPath.empty();
  Image exemplar = exemplarFallback ? proceduralMarble(args.exemplarSize, globals.seed)
                                    : centerCrop(readImage(exemplarPath), args.exemplarSize);
  writeImage(out("exemplar.png"), exemplar);
  report["exemplar"] = {{"source", exemplarFallback ? "procedural marble" : exemplarPath},
                        {"fallback", exemplarFallback},
                        {"width", exemplar.width},
                        {"height", exemplar.height}};
  say(globals, "exemplar: " + report["exemplar"]["source"].get<std::string>());

  // Analysis, through the on-disk cache.
  AnalysisOptions options;
  auto start = std::chrono::steady_clock::now();
  std::string cacheDir = args.cacheDir.empty() ? defaultCacheDirectory() : args.cacheDir;
  std::uint64_t key = analysisCacheKey(exemplar, options);
  std::optional<ExemplarAnalysis> hit = loadCachedAnalysis(analysisCachePath(cacheDir, key), key);
  bool cached = hit.has_value();
  ExemplarAnalysis analysis = cached ? std::move(*hit) : analyzeExemplarCached(exemplar, options, cacheDir, *progress);
  double analysisSeconds = secondsSince(start);
  json levels = json::array();
  for (int l = 0; l < analysis.levelCount(); ++l) {
    const ExemplarLevel& level = analysis.levels[l];
    levels.push_back({{"level", l},
                      {"spacing", level.spacing},
                      {"dimensions", level.pca.outputDimension},
                      {"kept_energy", level.pca.keptEnergy}});
  }
  report["analysis"] = {{"seconds", analysisSeconds}, {"cached", cached}, {"neighborhood", analysis.neighborhoodSize},
                        {"k", analysis.similarCount}, {"levels", levels}, {"cache_directory", cacheDir}};
  writeImage(out("gaussian_stack.png"), stackPicture(analysis));

  // Mesh: the user's, else CGAL's bunny, else a sphere.
  std::string meshPath = args.mesh;
  if (meshPath.empty()) meshPath = cgalMesh(kDefaultMesh).value_or("");
  bool meshFallback = meshPath.empty();
  Mesh mesh = meshFallback ? makeUvSphereMesh(Vec3f::Zero(), 1.0f, 48, 96) : readMesh(meshPath);
  render.up = viewUpDirection(mesh);  // for every view of the mesh below (lazy solid, studio cut)
  start = std::chrono::steady_clock::now();
  progress->begin("rendering", 2);
  Image plain = renderViews(mesh, nullptr, views, render);
  progress->advance(1);
  double renderSeconds = secondsSince(start);
  // A solid texture from the 2D exemplar: tile-deform, stacked along x, y and z and blended by
  // the normal (paper eq. 3), evaluated at every rendered pixel.
  start = std::chrono::steady_clock::now();
  TileDeformSolidOptions solidOptions;
  solidOptions.placement = fitPlacement(mesh.bounds(), std::max(exemplar.width, exemplar.height));
  solidOptions.deformation.cellSize = Vec3f::Constant(0.25f * std::max(exemplar.width, exemplar.height));
  solidOptions.deformation.seed = globals.seed;
  std::unique_ptr<SolidTexture> solid = makeStackedTileDeformSolid(exemplar, solidOptions);
  SurfaceColorFunction colorAt = surfaceColorFunction(*solid);
  Image solidRender = renderViews(mesh, &colorAt, views, render);
  double solidSeconds = secondsSince(start);
  progress->advance(1);
  progress->end();
  writeImage(out("mesh.png"), plain);
  writeImage(out("mesh_solid.png"), solidRender);
  report["mesh"] = {{"source", meshFallback ? "built-in sphere" : meshPath},
                    {"fallback", meshFallback},
                    {"vertices", mesh.vertexCount()},
                    {"triangles", mesh.triangleCount()},
                    {"render_seconds", renderSeconds},
                    {"solid_render_seconds", solidSeconds}};

  // The plain-tiling baseline.
  MetricOptions metricOptions;
  metricOptions.seed = globals.seed;
  QualityMetrics tiling =
      evaluateImage(exemplar, exemplar.tiled(2 * exemplar.width, 2 * exemplar.height), metricOptions);
  report["tiling_baseline"] = metricsJson(tiling);
  report["tiling_baseline"]["seconds"] = tiling.seconds;

  progress->begin("2D synthesis", 1);
  report["pixel"] = demoPixelSynthesis(exemplar, analysis, globals.seed, cacheDir, out);
  progress->advance(1);
  progress->end();

  progress->begin("surface synthesis", 1);
  {
    const std::optional<std::string> fabric = gimpPattern(kSurfacePattern);
    const Image surfaceExemplar = fabric ? readImage(*fabric).withChannels(3) : exemplar;
    report["surface"] = demoSurfaceSynthesis(mesh, meshFallback ? "built-in sphere" : meshPath, surfaceExemplar,
                                             fabric ? *fabric : (exemplarFallback ? "procedural marble" : exemplarPath),
                                             globals.seed, cacheDir, out);
  }
  progress->advance(1);
  progress->end();

  progress->begin("flow animation", 1);
  report["animation"] =
      demoAnimation(exemplar, exemplarFallback ? "procedural marble" : exemplarPath, globals.seed, cacheDir, out);
  progress->advance(1);
  progress->end();

  progress->begin("lazy solid", 1);
  report["lazy_solid"] = demoLazySolid(mesh, exemplar, exemplarFallback ? "procedural marble" : exemplarPath,
                                       globals.seed, cacheDir, render, views, out);
  progress->advance(1);
  progress->end();

  progress->begin("studio", 1);
  report["studio"] = demoStudio(mesh, exemplar, cacheDir, render, out);
  progress->advance(1);
  progress->end();

  progress->begin("gradient solids", 1);
  report["gradient"] = demoGradientSolids(exemplar, globals.seed, cacheDir, out);
  progress->advance(1);
  progress->end();

  writeFileAtomically(out("report.json"), report.dump(2) + "\n");
  writeFileAtomically(out("report.md"), markdownReport(report));
  if (globals.json) printJsonWhenCommitted(report);
  sayWhenCommitted(
      globals,
      "wrote " + out("report.md") +
          " with exemplar.png, gaussian_stack.png, mesh.png, mesh_solid.png, pixel_synthesis.png, pixel_seams.png, "
          "surface_synthesis.png, animation_frames.png, animation_lambdas.png, animation.gif, lazy_solid.png, "
          "studio_cut.png, "
          "gradient_magnified.png, "
          "gradient_edit.png, gradient_synthesized.png and gradient_solid.tsgs");
}

}  // namespace

Command registerDemoCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "demo",
      "A tour on built-in defaults: analyse a real exemplar (GIMP's pink marble), render a real "
      "mesh (CGAL's bunny) plain and solid-textured, synthesize and score 2D textures, grow a "
      "texture on the mesh's surface, animate a texture along a flow, follow a sketched field with a lazy "
      "solid and cut it open, drive the studio's HTTP API, vectorize "
      "and edit a small gradient solid, and write a "
      "report with pictures into DIR");
  auto args = std::make_shared<DemoArgs>();
  sub->add_option("-o,--output", args->outputDir, "Directory for the report and pictures")->capture_default_str();
  inputFiles(sub->add_option("--exemplar", args->exemplar,
                             std::string("Exemplar image (default: gimp-data's ") + kDefaultPattern + ")"));
  inputFiles(sub->add_option("--mesh", args->mesh, std::string("Mesh (default: libcgal-demo's ") + kDefaultMesh + ")"));
  sub->add_option("--exemplar-size", args->exemplarSize, "Analyse the centre crop of this size")
      ->capture_default_str()
      ->check(integerIn(16, 1024));
  sub->add_option("--render-size", args->renderSize, "Size of each rendered view")
      ->capture_default_str()
      ->check(integerIn(16, 4096));
  sub->add_option("--cache", args->cacheDir,
                  "Directory of the exemplar-analysis cache (default: " + defaultCacheDirectory() + ")");
  const ParameterSources sources = {{"exemplar", fromFile(args->exemplar)}, {"image", fromFile(args->exemplar)},
                                    {"mesh", fromFile(args->mesh)},         {"bounds", fromFile(args->mesh)},
                                    {"box", fromFile(args->mesh)},          {"width", fromFlag("--render-size")},
                                    {"height", fromFlag("--render-size")}};
  return {sub, [args, &globals] { runDemo(*args, globals); }, sources, "--exemplar-size or --render-size"};
}

}  // namespace texsynth::cli
