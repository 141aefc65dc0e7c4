// texsynth animate EXEMPLAR --flow FLOW [--size N | --mesh M] -o frames/%04d.png -o anim.mp4: a
// texture flowing along a velocity field, frame after frame, coherent in time and faithful to
// the exemplar (flow animation by discrete optimization with E_c).
#include <chrono>
#include <cmath>

#include "animate_outputs.h"
#include "cli_common.h"
#include "mode_flags.h"
#include "number_checks.h"
#include "surface_setup.h"
#include "texsynth/animation/flow_limits.h"
#include "texsynth/animation/image_animation.h"
#include "texsynth/animation/image_flow.h"
#include "texsynth/animation/surface_animation.h"
#include "texsynth/animation/surface_flow.h"
#include "texsynth/core/error.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/core/timing.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/exemplar/gaussian_stack.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth::cli {
namespace {

using nlohmann::json;

struct AnimateArgs {
  std::string exemplar, flow, mesh, size = "512", stats, field, sketch, up, camera = "fixed";
  std::vector<std::string> outputs;
  int frames = 120, iterations = 1, vertices = 48000, levels = 3, renderSize = 512;
  float coherence = FlowAnimationOptions{}.coherence, flowScale = 1.0f, fps = 24.0f;
  float featureWeight = kSurfaceFeatureWeight;
};

// Peak memory of a 2D animation (frame 0's synthesis, then each frame's positions, sources,
// matches and colors), measured with `/usr/bin/time -f %M`: 82 MB at 512², 143 MB at 1024² (77
// bytes a pixel over a base of 62 MB); slope and base rounded up.
constexpr double kBaseBytes = 96.0 * 1024 * 1024, kBytesPerPixel = 160.0;

const std::vector<ModeFlag> kAnimateModeFlags = {
    {"--size", {"image"}}, {"--vertices", {"mesh"}}, {"--field", {"mesh"}},       {"--sketch", {"mesh"}},
    {"--up", {"mesh"}},    {"--camera", {"mesh"}},   {"--render-size", {"mesh"}}, {"--feature-weight", {"mesh"}},
};

// --flow checked as typed: a preset's keys and values, or a well-formed file pattern.
CLI::Validator flowSpecification() {
  return CLI::Validator(
      [](std::string& spec) -> std::string {
        try {
          checkFlowSpecification(spec);
        } catch (const ParameterError& e) {
          return e.problem();
        }
        return {};
      },
      "SPEC");
}

json frameJson(const FrameStatistics& s) {
  return {{"frame", s.frame},
          {"seconds", s.seconds},
          {"advect_seconds", s.advectSeconds},
          {"solve_seconds", s.solveSeconds},
          {"energy", s.energy},
          {"kept", s.keptFraction},
          {"solver_kept", s.solverKept},
          {"temporal_change", s.temporalChange}};
}

// Per-frame timings and temporal change over frames 1.. (frame 0 is the static synthesis).
void summarize(json& report, const std::vector<FrameStatistics>& frames) {
  json list = json::array();
  double seconds = 0, worst = 0, change = 0, kept = 0;
  for (const FrameStatistics& s : frames) {
    list.push_back(frameJson(s));
    if (s.frame == 0) continue;
    seconds += s.seconds, worst = std::max(worst, s.seconds), change += s.temporalChange, kept += s.keptFraction;
  }
  const double n = double(std::max<std::size_t>(frames.size(), 2) - 1);
  report["frames"] = list;
  report["first_frame_seconds"] = frames.empty() ? 0.0 : frames.front().seconds;
  report["mean_frame_seconds"] = seconds / n;
  report["max_frame_seconds"] = worst;
  report["mean_temporal_change"] = change / n;
  report["mean_kept"] = kept / n;
}

std::string formatted(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string summaryOf(const json& report, int frames, const std::string& what) {
  const double first = report["first_frame_seconds"].get<double>(), mean = report["mean_frame_seconds"].get<double>();
  return "animated " + std::to_string(frames) + " frames of " + what + ": first frame " +
         formatted(first < 1 ? "%.3f s" : "%.1f s", first) + ", then " + formatted("%.3f s", mean) +
         " per frame (temporal change " + formatted("%.2f", report["mean_temporal_change"].get<double>()) + " levels)";
}

void runImageAnimation(const CLI::App& parser, const AnimateArgs& args, const GlobalOptions& globals,
                       const FlowAnimationOptions& animation, FrameOutputs& outputs) {
  const Size2 size = parseSize(args.size, "--size");
  const ImageFlow flow = ImageFlow::parse(args.flow, size.width, size.height, {args.flowScale});
  flow.requireFrames(args.frames);
  const auto start = std::chrono::steady_clock::now();
  const Image exemplar = readImage(args.exemplar);
  TextureOptimizationOptions synthesis;
  synthesis.seed = globals.seed;
  synthesis.levels = parser.count("--levels")
                         ? args.levels
                         : std::min(synthesis.levels, defaultStackLevelCount(exemplar.width, exemplar.height));
  auto progress = makeProgress(globals);
  const std::string cache = defaultCacheDirectory();
  const std::vector<ExemplarAnalysis> analyses = cachedOptimizationAnalyses(exemplar, synthesis, cache, *progress);
  const ExemplarAnalysis parallel = analyzeExemplarCached(exemplar, {}, cache, *progress);
  json report = {{"exemplar", args.exemplar},
                 {"exemplar_size", {exemplar.width, exemplar.height}},
                 {"size", {size.width, size.height}},
                 {"flow", flow.description()},
                 {"coherence", animation.coherence},
                 {"iterations", animation.iterations},
                 {"seed", globals.seed}};
  report["analysis_seconds"] = secondsSince(start);

  ImageAnimator animator(analyses, &parallel, synthesis, animation, size.width, size.height, *progress);
  std::vector<FrameStatistics> frames{animator.statistics()};
  outputs.addPicture(0, animator.colors());
  progress->begin("animate " + std::to_string(args.frames) + " frames", args.frames - 1);
  for (int t = 1; t < args.frames; ++t) {
    animator.advance(flow.velocities(t - 1));
    frames.push_back(animator.statistics());
    outputs.addPicture(t, animator.colors());
    progress->advance(1);
  }
  progress->end();
  summarize(report, frames);
  report["outputs"] = outputs.finish();
  finishReport(
      globals, report, args.stats,
      summaryOf(report, args.frames,
                std::to_string(size.width) + "x" + std::to_string(size.height) + " (" + flow.description() + ")"));
}

void runSurfaceAnimation(const CLI::App& parser, const AnimateArgs& args, const GlobalOptions& globals,
                         const FlowAnimationOptions& animation, FrameOutputs& outputs) {
  SurfaceSetupArgs setupArgs;
  setupArgs.exemplar = args.exemplar, setupArgs.mesh = args.mesh, setupArgs.field = args.field;
  setupArgs.sketch = args.sketch, setupArgs.up = args.up, setupArgs.vertices = args.vertices;
  setupArgs.levels = args.levels, setupArgs.levelsGiven = parser.count("--levels") > 0;
  setupArgs.verticesGiven = parser.count("--vertices") > 0, setupArgs.featureWeight = args.featureWeight;
  json report;
  auto progress = makeProgress(globals);
  const SurfaceSetup setup = setUpSurface(setupArgs, globals, report, *progress);
  const PreparedSurface& surface = *setup.surface;
  const Mesh& finest = surface.finestMesh();
  const PreparedSurfaceLevel& finestLevel = surface.levels.back();
  std::vector<Vec3f> fieldUp(finest.positions.size());
  for (std::size_t v = 0; v < fieldUp.size(); ++v) fieldUp[v] = finest.normals[v].cross(finestLevel.tangents[v]);
  SurfaceFlowOptions flowOptions;
  flowOptions.scale = args.flowScale;
  if (!args.up.empty()) flowOptions.up = parseDirection(args.up, "--up");
  const SurfaceFlow flow = namingMesh(args.mesh, [&] {
    return SurfaceFlow::parse(args.flow, setup.input,
                              SurfaceFlowMesh{&finest, fieldUp, surface.hierarchy.levels.back().spacing}, flowOptions);
  });
  flow.requireFrames(args.frames);
  report["flow"] = flow.description();
  report["coherence"] = animation.coherence;
  report["iterations"] = animation.iterations;
  report["vertices"] = finest.vertexCount();

  RenderOptions render;
  render.width = render.height = args.renderSize;
  render.up = viewUp(args.up, finest);
  Mesh colored = finest;
  colored.attributes.clear();
  SurfaceAnimator animator(setup.analyses, surface, setup.options, animation, *progress);
  std::vector<FrameStatistics> frames{animator.statistics()};
  double renderSeconds = 0;
  auto emit = [&](int t) {
    colored.colors = animator.colors();
    if (outputs.wantsMeshes()) outputs.addMesh(t, colored);
    if (!outputs.wantsPictures()) return;
    const auto start = std::chrono::steady_clock::now();
    if (args.camera == "orbit") render.yawDegrees = 30.0f + 360.0f * float(t) / float(args.frames);
    const Image picture = renderMesh(colored, render);
    renderSeconds += secondsSince(start);
    outputs.addPicture(t, picture);
  };
  emit(0);
  progress->begin("animate " + std::to_string(args.frames) + " frames", args.frames - 1);
  for (int t = 1; t < args.frames; ++t) {
    animator.advance(flow.velocities(t - 1));
    frames.push_back(animator.statistics());
    emit(t);
    progress->advance(1);
  }
  progress->end();
  summarize(report, frames);
  report["render_seconds"] = renderSeconds;
  report["outputs"] = outputs.finish();
  finishReport(
      globals, report, args.stats,
      summaryOf(report, args.frames, std::to_string(finest.vertexCount()) + " vertices (" + flow.description() + ")"));
}

void runAnimate(const CLI::App& parser, const AnimateArgs& args, const GlobalOptions& globals) {
  const bool onMesh = !args.mesh.empty();
  rejectFlagsOutsideMode(parser, kAnimateModeFlags, onMesh ? "mesh" : "image",
                         onMesh ? "with --mesh" : "without --mesh");
  if (args.camera != "fixed" && args.camera != "orbit")
    throw ParameterError("--camera", "must be 'fixed' or 'orbit', got '" + args.camera + "'");
  if (!args.up.empty() && (!args.field.empty() || !args.sketch.empty()))
    throw ParameterError("--up",
                         "sets the default field's direction; with --field or --sketch that field orients "
                         "the texture: drop one");
  FlowAnimationOptions animation;
  animation.coherence = args.coherence;
  animation.iterations = args.iterations;
  validateFlowAnimationOptions(animation);
  if (onMesh) {
    RenderOptions render;
    render.width = render.height = args.renderSize;
    requireMemory(surfaceSynthesisBytes(args.vertices) + renderMemoryBytes(render, 1), "--vertices or --render-size",
                  std::to_string(args.vertices) + " vertices");
  } else {
    const Size2 size = parseSize(args.size, "--size");
    requireMemory(kBaseBytes + double(size.width) * double(size.height) * kBytesPerPixel, "--size",
                  "a " + std::to_string(size.width) + "x" + std::to_string(size.height) + " animation");
  }
  FrameOutputs outputs(args.outputs, onMesh, args.fps);
  if (onMesh)
    runSurfaceAnimation(parser, args, globals, animation, outputs);
  else
    runImageAnimation(parser, args, globals, animation, outputs);
}

ParameterSources animateParameterSources(const AnimateArgs& args) {
  return {{"exemplar", fromFile(args.exemplar)},
          {"image", fromFile(args.exemplar)},
          {"channels", fromFile(args.exemplar)},
          {"similarCount", fromFile(args.exemplar)},
          {"flow", fromFlag("--flow")},
          {"coherence", fromFlag("--coherence")},
          {"iterations", fromFlag("--iterations")},
          {"width", fromFlag("--size")},
          {"height", fromFlag("--size")},
          {"vertices", fromFlag("--vertices")},
          {"levels", fromFlag("--levels")},
          {"levelCount", fromFlag("--levels")},
          {"guide", fromFlag("--up")},
          {"flowScale", fromFlag("--flow-scale")}};
}

}  // namespace

Command registerAnimateCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "animate",
      "Animate a texture flowing along a velocity field (flow animation by discrete optimization, Han et al. with "
      "Kwatra et al.'s E_c): frame 0 is synthesized as `image --method optimize` (or `surface` with --mesh) does; "
      "every next frame carries the previous one along the flow and lets the solver repair it where the flow "
      "stretches or squeezes the texture, so it stays both coherent in time and faithful to the exemplar, also "
      "around sources and sinks where texture must appear or vanish.\n"
      "  Flows (--flow) in 2D: uniform:dx=1,dy=0 | vortex | source | sink | saddle, with :strength=S (pixels per "
      "frame),cx=X,cy=Y (centre, fractions of the size),radius=R; or a velocity image the size of the output (EXR: "
      "pixels per frame in R,G; PNG: 2c-1); a frame number in the name (flow/%04d.exr) gives one per frame.\n"
      "  Flows on a mesh (--mesh): along-field | downhill | swirl, with :strength=S (vertex spacings per frame); or "
      "a text file with one 'vx vy vz' per input-mesh vertex (world units per frame), or a numbered pattern.\n"
      "  --coherence (lambda) trades time against fidelity: 0 = independent frames (flicker), large = pure advection "
      "(drifts and smears).\n"
      "  Outputs (-o, repeatable): numbered frames (frames/%04d.png: the texture, or the rendered mesh), numbered "
      "vertex-colored meshes with --mesh (colors/%04d.ply), videos (.mp4 .webm .gif, needs ffmpeg).\n"
      "Example: texsynth animate pink_marble.png --flow vortex:strength=2 --frames 120 -o frames/%04d.png -o "
      "vortex.mp4");
  auto args = std::make_shared<AnimateArgs>();
  inputFiles(sub->add_option("EXEMPLAR", args->exemplar, "Exemplar image"))->required();
  inputFiles(sub->add_option("--flow", args->flow, "Velocity field: a preset (see above) or a velocity file / pattern")
                 ->required()
                 ->check(flowSpecification()),
             &args->frames);
  outputFiles(sub->add_option("-o,--output", args->outputs,
                              "frames/%04d.png, colors/%04d.ply (--mesh), anim.mp4 / .webm / .gif; may be repeated"),
              &args->frames);
  sub->add_option("--frames", args->frames, "Frames to make (frame 0 included)")
      ->capture_default_str()
      ->check(integerIn(1, 100000));
  sub->add_option("--coherence", args->coherence,
                  "lambda of E_c: weight of the previous frame carried along the flow against the texture votes (0 = "
                  "independent frames)")
      ->capture_default_str()
      ->check(finiteIn(0, kMaxFlowCoherence));
  sub->add_option("--iterations", args->iterations, "E+M steps per frame at the finest level")
      ->capture_default_str()
      ->check(integerIn(1, 20));
  sub->add_option("--fps", args->fps, "Frames per second of the videos")
      ->capture_default_str()
      ->check(finiteIn(1, 240));
  sub->add_option("--flow-scale", args->flowScale, "Multiplies every velocity (to slow down or reverse a flow)")
      ->capture_default_str()
      ->check(finiteIn(-kMaxFlowScale, kMaxFlowScale));
  sub->add_option("--size", args->size, "Output size in 2D, WxH or N (multiples of 4; the animation tiles)")
      ->capture_default_str();
  sub->add_option("--levels", args->levels, "Levels of frame 0's synthesis (default 3, fewer for a small exemplar)")
      ->check(integerIn(1, 6));
  inputFiles(
      sub->add_option("--mesh", args->mesh, "Animate on this mesh's surface (" + readableMeshExtensions() + ")"));
  sub->add_option("--vertices", args->vertices, "With --mesh: vertices of the retiled mesh (the texture's density)")
      ->capture_default_str()
      ->check(integerIn(64, 5000000));
  auto* field =
      inputFiles(sub->add_option("--field", args->field, "With --mesh: rotation field orienting the texture"));
  inputFiles(sub->add_option("--sketch", args->sketch, "With --mesh: sketch curves to design the field from"))
      ->excludes(field);
  sub->add_option("--up", args->up,
                  std::string("With --mesh: X,Y,Z world up (the default field and `downhill`; default 0,1,0), and the "
                              "rendered model's up (default: ") +
                      kViewUpRule + ")");
  sub->add_option("--feature-weight", args->featureWeight,
                  "With --mesh: weight of the feature channel (as `texsynth surface --feature-weight`)")
      ->capture_default_str()
      ->check(finiteIn(0, 10));
  sub->add_option("--camera", args->camera, "With --mesh: 'fixed' or 'orbit' (one turn over the animation)")
      ->capture_default_str();
  sub->add_option("--render-size", args->renderSize, "With --mesh: pixel size of the rendered frames")
      ->capture_default_str()
      ->check(integerIn(16, 4096));
  outputFiles(sub->add_option("--stats", args->stats,
                              "Write per-frame timings, energy, kept share and temporal change as JSON here"));
  return {sub, [sub, args, &globals] { runAnimate(*sub, *args, globals); }, animateParameterSources(*args),
          "--size, --vertices or --render-size"};
}

}  // namespace texsynth::cli
