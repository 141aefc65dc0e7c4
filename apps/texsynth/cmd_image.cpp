// texsynth image EXEMPLAR --method tile-deform|tile-blend|parallel|optimize: a 2D texture of any
// size (or any window of the infinite texture, for the random-access methods) from one exemplar;
// or, with --apply-coords, another map of the same material through a stored synthesis.
#include <chrono>
#include <cstdio>

#include "image_args.h"
#include "mode_flags.h"
#include "number_checks.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/image/make_tileable.h"
#include "texsynth/image/seam_blend.h"
#include "texsynth/image/tile_blend.h"
#include "texsynth/image/tile_deform.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

DeformDirections parseDirections(const std::string& text) {
  if (text == "both") return DeformDirections::Both;
  if (text == "x") return DeformDirections::XOnly;
  return DeformDirections::YOnly;
}

// Makes the exemplar tileable when asked, or when its wrap-around seams are visible ("auto").
Image prepareExemplar(const ImageArgs& args, const ImageWriteOptions& keepPrecision, json& report) {
  Image exemplar = readImage(args.exemplar);
  SeamStrength before = measureSeams(exemplar);
  report["seam_ratio_before"] = before.ratio();
  bool convert = args.tileable == "always" || (args.tileable == "auto" && before.ratio() > args.seamThreshold);
  if (convert) {
    exemplar = makeTileable(exemplar);
    report["seam_ratio_after"] = measureSeams(exemplar).ratio();
  }
  report["made_tileable"] = convert;
  if (!args.saveTileable.empty()) writeImage(args.saveTileable, exemplar, keepPrecision);
  return exemplar;
}

void finish(const ImageArgs& args, const GlobalOptions& globals, const ImageFileInfo& exemplarInfo,
            const Window& window, Image result, double seconds, json& report);

const std::vector<std::string> kSynthesisModes = {"tile-deform", "tile-blend", "parallel", "optimize"};

// Which modes (a --method, or --apply-coords) use each mode-specific flag.
const std::vector<ModeFlag> kImageModeFlags = {
    {"--method", kSynthesisModes},
    {"--size", kSynthesisModes},
    {"--window", {"tile-deform", "tile-blend", "parallel"}},  // optimize solves for a whole image at once
    {"--tileable", kSynthesisModes},
    {"--seam-threshold", kSynthesisModes},
    {"--save-tileable", kSynthesisModes},
    {"--cell", {"tile-deform"}},
    {"--lambda", {"tile-deform"}},
    {"--clamp", {"tile-deform"}},
    {"--noise-frequency", {"tile-deform"}},
    {"--directions", {"tile-deform"}},
    {"--tile-size", {"tile-blend"}},
    {"--blend-exponent", {"tile-blend"}},
    {"--passes", {"parallel"}},
    {"--subpasses", {"parallel"}},
    {"--footprint", {"parallel"}},
    {"--jitter", {"parallel", "optimize"}},
    {"--levels", {"parallel", "optimize"}},
    {"--neighborhood", {"parallel", "optimize"}},
    {"-k", {"parallel", "optimize"}},
    {"--coords", {"parallel", "optimize"}},
    {"--solver", {"optimize"}},
    {"--iterations", {"optimize"}},
    {"--coverage", {"optimize"}},
    {"--start", {"optimize"}},
    {"--vote-exponent", {"optimize"}},
    {"--seam-blend", {"optimize", "--apply-coords"}},
};

// Where the library's parameters come from on `image`'s command line.
ParameterSources imageParameterSources(const ImageArgs& args) {
  return {{"exemplar", fromFile(args.exemplar)},
          {"image", fromFile(args.exemplar)},
          {"channels", fromFile(args.exemplar)},
          {"width", fromFlag("--size")},
          {"height", fromFlag("--size")},
          {"x0", fromFlag("--window")},
          {"y0", fromFlag("--window")},
          {"cellWidth", fromFlag("--cell")},
          {"cellHeight", fromFlag("--cell")},
          {"lambdaX", fromFlag("--lambda")},
          {"lambdaY", fromFlag("--lambda")},
          {"maxDisplacement", fromFlag("--clamp")},
          {"noiseFrequency", fromFlag("--noise-frequency")},
          {"tileSize", fromFlag("--tile-size")},
          {"weightExponent", fromFlag("--blend-exponent")},
          {"passes", fromFlag("--passes")},
          {"subpasses", fromFlag("--subpasses")},
          {"coarsestFootprint", fromFlag("--footprint")},
          {"jitter", fromFlag("--jitter")},
          {"levels", fromFlag("--levels")},
          {"levelCount", fromFlag("--levels")},
          {"neighborhood", fromFlag("--neighborhood")},
          {"neighborhoodSize", fromFlag("--neighborhood")},
          {"levelNeighborhoodSizes", fromFlag("--neighborhood")},
          {"similarCount", fromFlag("-k")},
          {"solver", fromFlag("--solver")},
          {"iterations", fromFlag("--iterations")},
          {"coverageWeight", fromFlag("--coverage")},
          {"start", fromFlag("--start")},
          {"voteExponent", fromFlag("--vote-exponent")},
          {"seamBlend", fromFlag("--seam-blend")}};
}

// Source coordinates are pixel indices into exemplars of up to 65536 pixels a side: only float
// EXR holds them exactly (8 and 16-bit formats would clamp and round them).
void requireCoordinateFile(const std::string& path, const std::string& flag) {
  if (!path.empty() && fileExtension(path) != "exr")
    throw ParameterError(flag, "'" + path + "': source coordinates are stored only as float EXR (.exr)");
}

// Refuses, before any work, an output too big for this machine. Peak bytes per output pixel, measured at 512² and
// 1024² (`/usr/bin/time -f %M`), rounded up: the float result, the method's own maps, and the encoder's buffers.
void requireImageMemory(const ImageArgs& args, const Window& window) {
  const double bytesPerPixel = args.method == "optimize" && args.applyCoords.empty() ? 128.0 : 64.0;
  requireMemory(double(window.width) * double(window.height) * bytesPerPixel,
                args.window.empty() ? "--size" : "--window",
                "a " + std::to_string(window.width) + "x" + std::to_string(window.height) + " image");
}

void runImage(const CLI::App& parser, const ImageArgs& args, const GlobalOptions& globals) {
  if (fileKind(args.output) != FileKind::Image)
    throw ParameterError("--output",
                         "'" + args.output + "' is not an image file name (" + readableImageExtensions() + ")");
  Window window;
  if (!args.window.empty()) {
    window = parseWindow(args.window, "--window");
  } else {
    Size2 size = parseSize(args.size, "--size");
    window.width = size.width, window.height = size.height;
  }
  requireImageMemory(args, window);
  const std::string mode = args.applyCoords.empty() ? args.method : "--apply-coords";
  rejectFlagsOutsideMode(parser, kImageModeFlags, mode,
                         "with " + (args.applyCoords.empty() ? "--method " + mode : mode));
  requireCoordinateFile(args.coords, "--coords");
  requireCoordinateFile(args.applyCoords, "--apply-coords");
  // Read once: the outputs keep the exemplar's precision where their format can.
  const ImageFileInfo exemplarInfo = readImageInfo(args.exemplar);
  json report = {{"exemplar", args.exemplar}, {"method", args.method}, {"seed", globals.seed}};
  if (!args.applyCoords.empty()) {
    report["method"] = "apply-coords";
    report["made_tileable"] = false;
    Image result = applyCoordinates(readImage(args.exemplar), args, report);
    window.width = result.width, window.height = result.height;
    return finish(args, globals, exemplarInfo, window, std::move(result), 0.0, report);
  }
  Image exemplar = prepareExemplar(args, writeOptionsKeeping(exemplarInfo), report);

  auto start = std::chrono::steady_clock::now();
  Image result;
  if (args.method == "tile-deform") {
    TileDeformOptions options;
    std::tie(options.cellWidth, options.cellHeight) = parseFloatPair(args.cell, "--cell");
    std::tie(options.lambdaX, options.lambdaY) = parseFloatPair(args.lambda, "--lambda");
    options.maxDisplacement = args.clamp;
    options.noiseFrequency = args.noiseFrequency;
    options.directions = parseDirections(args.directions);
    options.seed = globals.seed;
    TileDeformTexture texture(exemplar, options);
    report["cell"] = {texture.cellWidth(), texture.cellHeight()};
    result = texture.synthesizeWindow(window.x, window.y, window.width, window.height);
  } else if (args.method == "parallel") {
    result = synthesizeParallelWindow(exemplar, args, window, globals, report);
  } else if (args.method == "optimize") {
    result = synthesizeOptimized(exemplar, args, window.width, window.height, globals, report);
  } else {
    TileBlendOptions options;
    options.tileSize = args.tileSize;
    options.weightExponent = args.blendExponent;
    options.seed = globals.seed;
    result = synthesizeTileBlend(exemplar, options, window.x, window.y, window.width, window.height);
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  finish(args, globals, exemplarInfo, window, std::move(result), seconds, report);
}

// Writes the result and reports it.
void finish(const ImageArgs& args, const GlobalOptions& globals, const ImageFileInfo& exemplarInfo,
            const Window& window, Image result, double seconds, json& report) {
  // Keeps the exemplar's precision where the format can: a 16-bit input gives a 16-bit PNG, an
  // 8-bit one a half-float EXR; other formats store 8 bits, which the user is told.
  writeImage(args.output, result, writeOptionsKeeping(exemplarInfo));
  const std::string ext = fileExtension(args.output);
  if (exemplarInfo.bitsPerChannel > 8 && ext != "png" && ext != "exr")
    say(globals, "note: " + args.output + " stores 8 bits per channel, the exemplar has " +
                     std::to_string(exemplarInfo.bitsPerChannel) + "; write .png or .exr to keep them");

  report["window"] = {window.x, window.y, window.width, window.height};
  report["seconds"] = seconds;
  report["megapixels_per_second"] = double(window.width) * window.height / 1e6 / std::max(seconds, 1e-9);
  report["output"] = args.output;
  if (globals.json) return printJsonWhenCommitted(report);
  char line[160];
  std::snprintf(line, sizeof line, "wrote %s (%dx%d, %s, %.3f s)%s", args.output.c_str(), window.width, window.height,
                report["method"].get<std::string>().c_str(), seconds,
                report["made_tileable"].get<bool>() ? "; exemplar made tileable first" : "");
  sayWhenCommitted(globals, line);
}

}  // namespace

Command registerImageCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "image",
      "Synthesize a 2D texture from an exemplar. tile-deform, tile-blend and parallel are random access: --window "
      "X,Y,W,H computes any part of the infinite texture alone, bit-identical to the same region of a larger output.\n"
      "  tile-deform: tile the exemplar and deform a grid over it with Perlin noise (Chen et al.); keeps features "
      "crisp, suits irregular and near-stochastic textures (marble, stone, bark).\n"
      "  tile-blend: histogram-preserving tiling and blending (Heitz & Neyret 2018); no visible deformation, keeps "
      "the exemplar's histogram, suits stochastic textures (granite, sand, noise-like surfaces).\n"
      "  parallel: Lefebvre & Hoppe 2005 k-coherence synthesis on the cached exemplar analysis, from random "
      "coordinates; copies exemplar content pixel by pixel: fast, crisp, complete, no lattice, but many small "
      "seams.\n"
      "  optimize: texture optimization (Kwatra et al. 2005) with the discrete k-coherence solver of Han et al., "
      "started from the parallel result: slower, global (no --window), best at keeping larger structures intact "
      "and every part of the exemplar; --solver least-squares runs Kwatra's original blended solver for comparison "
      "(blurrier, slower).\n"
      "With --apply-coords COORDS.exr, EXEMPLAR is another map of the same material (normal, roughness ...) and the "
      "stored synthesis (from --coords) is re-applied to it.");
  auto args = std::make_shared<ImageArgs>();
  inputFiles(sub->add_option("EXEMPLAR", args->exemplar, "Exemplar image"))->required();
  outputFiles(sub->add_option("-o,--output", args->output, "Output image (.png .jpg .exr ...)"))->required();
  sub->add_option("--method", args->method, "Synthesis method")
      ->capture_default_str()
      ->check(CLI::IsMember({"tile-deform", "tile-blend", "parallel", "optimize"}));
  sub->add_option("--size", args->size, "Output size WxH or N (the window at the origin)")->capture_default_str();
  sub->add_option("--window", args->window,
                  "X,Y,W,H: the window of the infinite texture to compute (overrides --size); within +-2^28 of the "
                  "origin");
  sub->add_option("--tileable", args->tileable,
                  "Make the exemplar tileable first (minimum-error cut across its wrap edges): auto = when its seams "
                  "are visible (seam ratio above --seam-threshold)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "always", "never"}));
  sub->add_option("--seam-threshold", args->seamThreshold,
                  "Seam ratio (wrap-edge difference / interior difference) above which 'auto' converts")
      ->capture_default_str()
      ->check(finiteIn(0, 1e6));
  outputFiles(
      sub->add_option("--save-tileable", args->saveTileable, "Also write the (possibly converted) exemplar here"));
  auto* deform = "tile-deform";
  sub->add_option("--cell", args->cell,
                  std::string(deform) + ": grid cell size SX[,SY] in pixels (0 = a quarter of the exemplar)")
      ->capture_default_str();
  sub->add_option("--lambda", args->lambda,
                  std::string(deform) + ": noise factors LX[,LY] (displacement = noise * lambda * cell)")
      ->capture_default_str();
  sub->add_option("--clamp", args->clamp,
                  std::string(deform) + ": largest displacement as a fraction of the cell (< 0.5, so cells never fold)")
      ->capture_default_str()
      ->check(finiteIn(0, 0.5, true));
  sub->add_option("--noise-frequency", args->noiseFrequency, std::string(deform) + ": noise periods per grid cell")
      ->capture_default_str()
      ->check(finiteIn(0.001, 1000));
  sub->add_option("--directions", args->directions, std::string(deform) + ": deform both axes, or only x or only y")
      ->capture_default_str()
      ->check(CLI::IsMember({"both", "x", "y"}));
  addTileBlendOptions(*sub, args->tileSize, args->blendExponent);
  sub->add_option("--passes", args->passes, "parallel: correction passes per level")
      ->capture_default_str()
      ->check(integerIn(0, 16));
  sub->add_option("--jitter", args->jitter,
                  "parallel: jitter strength for all levels, or COARSEST,OTHERS (default 0.4 everywhere; raise the "
                  "coarsest to break large-scale repetition). optimize: jitter of the levels after the coarsest "
                  "(default 0; the optimization removes most of it)");
  sub->add_option("--solver", args->solver,
                  "optimize: discrete (k-coherence E- and M-steps, Han et al.) or least-squares (Kwatra et al. 2005)")
      ->capture_default_str()
      ->check(CLI::IsMember({"discrete", "least-squares"}));
  sub->add_option("--levels", args->levels,
                  "parallel, optimize: Gaussian stack levels (0 = as many as the exemplar allows; default: parallel 0, "
                  "optimize 3 as Han et al.)")
      ->check(integerIn(0, 16));
  sub->add_option("--neighborhood", args->neighborhoods,
                  "parallel: neighborhood size N per level, coarsest first, the last repeating (default 5, as L&H "
                  "2005; e.g. 5,7). optimize: sizes run in turn at every level (default 17,9, Han et al. Table 2)");
  sub->add_option("--iterations", args->iterations,
                  "optimize: most E+M iterations per level and neighborhood size (stops when no match changes; "
                  "default 2, and 1 at the finest level, which the coarser ones have settled)")
      ->check(integerIn(1, 100));
  sub->add_option("--coverage", args->coverage,
                  "optimize (discrete): weight of the exemplar-coverage term, which makes over-used exemplar regions "
                  "cost more and unused ones less so that no part of the exemplar is dropped (default 0.15; 0 = the "
                  "plain energy)")
      ->check(finiteIn(0, 100));
  sub->add_option("--vote-exponent", args->voteExponent,
                  "optimize (discrete): the E-step weighs each match's vote by (its mean color distance per pixel + "
                  "0.01)^-E, so well-aligned matches decide and thin features survive (default 4; 0 = equal votes, "
                  "Han et al.)")
      ->check(finiteIn(0, 16));
  sub->add_option("--seam-blend", args->seamBlend,
                  "optimize (discrete): feather the seams between exemplar pieces over a Gaussian of this many "
                  "output pixels, as G'MIC blends its patches; pixels inside a coherent piece keep their exact "
                  "color, and --coords stays crisp (default 1.5; 0 = crisp cuts). --apply-coords feathers the same "
                  "way, so that optimize's coordinates re-apply to the image it wrote; pass 0 for parallel's")
      ->check(finiteIn(0, kMaxSeamBlend));
  sub->add_option("--start", args->start,
                  "optimize (discrete): start from parallel synthesis as Lefebvre & Hoppe 2005 publish it (keeps every "
                  "part of the exemplar, no lattice), from random exemplar patches, or from random pixels (Han et al.)")
      ->capture_default_str()
      ->check(CLI::IsMember({"parallel", "patches", "pixels"}));
  sub->add_option("-k,--similar", args->similarCount,
                  "parallel, optimize: k of the k-coherence similarity sets (default: parallel 2, optimize 4)")
      ->check(integerIn(1, 64));
  sub->add_option("--footprint", args->footprint,
                  "parallel: start at the coarsest level whose neighborhood spans at most this fraction of the "
                  "exemplar's smaller side, from random coordinates (default 0.5; 0 = Lefebvre & Hoppe 2005's "
                  "coarsest level from the tiled exemplar, which keeps tileable exemplars on a lattice)")
      ->check(finiteIn(0, 16));
  sub->add_option("--subpasses", args->subpasses,
                  "parallel: s, for s^2 subpasses per correction pass (1 = all pixels at once)")
      ->capture_default_str()
      ->check(integerIn(1, 4));
  outputFiles(
      sub->add_option("--coords", args->coords,
                      "parallel, optimize (discrete): also write the synthesized source coordinates (x, y into the "
                      "exemplar as used, i.e. after --tileable conversion: see --save-tileable) to this .exr"));
  inputFiles(
      sub->add_option("--apply-coords", args->applyCoords,
                      "Re-apply a synthesis: look EXEMPLAR (another map of the same material, the size of the original "
                      "exemplar) up at the coordinates in this .exr (from --coords); no synthesis runs"));
  return {sub, [sub, args, &globals] { runImage(*sub, *args, globals); }, imageParameterSources(*args),
          "--size or --window"};
}

}  // namespace texsynth::cli
