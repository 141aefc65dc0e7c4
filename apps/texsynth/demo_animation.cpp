// The demo's animation section: one vortex, three lambdas, per-frame time, temporal change and
// coherence.
#include "demo_animation.h"

#include <sstream>

#include "animate_outputs.h"
#include "cli_common.h"
#include "demo_pixel.h"
#include "texsynth/animation/image_animation.h"
#include "texsynth/animation/image_flow.h"
#include "texsynth/core/error.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/video_io.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

constexpr int kSide = 192, kFrames = 36, kIndependentFrames = 3;
const char* kFlow = "vortex:strength=1.5";

struct Run {
  std::vector<Image> frames;  // every frame (the filmstrip and the GIF read them)
  double frameSeconds = 0, temporalChange = 0;
};

Run animate(std::span<const ExemplarAnalysis> analyses, const ExemplarAnalysis& parallel, std::uint64_t seed,
            float coherence, int frames, const ImageFlow& flow) {
  TextureOptimizationOptions synthesis;
  synthesis.seed = seed;
  FlowAnimationOptions options;
  options.coherence = coherence;
  ImageAnimator animator(analyses, &parallel, synthesis, options, kSide, kSide);
  Run run;
  run.frames.push_back(animator.colors());
  for (int t = 1; t < frames; ++t) {
    animator.advance(flow.velocities(t - 1));
    run.frames.push_back(animator.colors());
    run.frameSeconds += animator.statistics().seconds / (frames - 1);
    run.temporalChange += animator.statistics().temporalChange / (frames - 1);
  }
  return run;
}

}  // namespace

json demoAnimation(const Image& exemplar, const std::string& exemplarName, std::uint64_t seed,
                   const std::string& cacheDirectory, const std::function<std::string(const std::string&)>& out) {
  TextureOptimizationOptions synthesis;
  const std::vector<ExemplarAnalysis> analyses = cachedOptimizationAnalyses(exemplar, synthesis, cacheDirectory);
  const ExemplarAnalysis parallel = analyzeExemplarCached(exemplar, {}, cacheDirectory);
  const ImageFlow flow = ImageFlow::parse(kFlow, kSide, kSide);
  const float defaultLambda = FlowAnimationOptions{}.coherence;

  json section = {{"exemplar", exemplarName},
                  {"flow", flow.description()},
                  {"size", kSide},
                  {"frames", kFrames},
                  {"runs", json::array()}};
  MetricOptions metrics;
  metrics.seed = seed;
  std::vector<Image> lastFrames;
  Run main;
  for (float lambda : {defaultLambda, 0.0f, 1e6f}) {
    const int frames = lambda == 0.0f ? kIndependentFrames : kFrames;  // independent frames are static syntheses
    Run run = animate(analyses, parallel, seed, lambda, frames, flow);
    const QualityMetrics quality = evaluateImage(exemplar, run.frames.back(), metrics);
    section["runs"].push_back({{"coherence_lambda", lambda},
                               {"frames", frames},
                               {"frame_seconds", run.frameSeconds},
                               {"temporal_change", run.temporalChange},
                               {"last_frame_coherence", quality.coherence}});
    lastFrames.push_back(run.frames.back());
    if (lambda == defaultLambda) main = std::move(run);
  }
  std::vector<Image> strip;
  for (int t = 0; t < kFrames; t += (kFrames - 1) / 3) strip.push_back(main.frames[std::size_t(t)]);
  writeImage(out("animation_frames.png"), sideBySide(strip, 4));
  writeImage(out("animation_lambdas.png"), sideBySide(lastFrames, 4));
  try {
    FrameOutputs gif({out("animation.gif")}, false, 12.0);
    for (int t = 0; t < kFrames; ++t) gif.addPicture(t, main.frames[std::size_t(t)]);
    gif.finish();
    section["gif"] = true;
  } catch (const OutputError& e) {  // no ffmpeg: the filmstrip alone
    section["gif"] = false;
    section["gif_problem"] = e.what();
  }
  return section;
}

std::string animationMarkdown(const json& animation) {
  std::ostringstream md;
  md << "## Flow animation\n\n![frames 0, 11, 22 and 33 at the default lambda](animation_frames.png)\n\n"
        "![the last frame at lambda = default, 0 (independent frames) and 1e6 (pure advection)]"
        "(animation_lambdas.png)\n\n";
  if (animation["gif"].get<bool>()) md << "![the animation](animation.gif)\n\n";
  md << "`texsynth animate " << animation["exemplar"].get<std::string>() << " --flow " << kFlow << " --size "
     << animation["size"] << " --frames " << animation["frames"]
     << "`: frame 0 is a static synthesis; every next frame carries the previous one's exemplar positions along "
        "the flow and runs one E+M step of the discrete solver per neighborhood size (17x17, then 9x9) with the "
        "carried "
        "colors as the constraint E_c (weight lambda). Temporal change: mean |frame t+1 - frame t carried along the "
        "flow| in 8-bit levels "
        "(lower = smoother); coherence of the last frame as `texsynth eval` measures it (lower = more like the "
        "exemplar).\n\n";
  md << "| lambda | frames | seconds per frame | temporal change | last frame's coherence "
        "|\n|---|---:|---:|---:|---:|\n";
  for (const json& run : animation["runs"]) {
    const float lambda = run["coherence_lambda"].get<float>();
    md << "| "
       << (lambda == 0      ? "0 (independent frames)"
           : lambda >= 1e5f ? "1e6 (pure advection)"
                            : fixed3(lambda) + " (default)")
       << " | " << run["frames"] << " | " << fixed3(run["frame_seconds"]) << " | " << fixed3(run["temporal_change"])
       << " | " << fixed3(run["last_frame_coherence"]) << " |\n";
  }
  md << "\n";
  return md.str();
}

}  // namespace texsynth::cli
