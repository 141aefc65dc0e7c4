// texsynth eval EXEMPLAR OUTPUT: coherence, completeness, histogram, periodicity, lattice and
// sharpness of a result.
#include <cstdio>

#include "cli_common.h"
#include "mode_flags.h"
#include "number_checks.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/volume_io.h"

namespace texsynth::cli {

using nlohmann::json;

static json toJson(const QualityMetrics& m) {
  json metrics = metricsJson(m);
  metrics["seconds"] = m.seconds;
  return metrics;
}

// One row of the volume table; lattice comes after sharpness so that scripts reading the first
// five metric columns keep working.
static void printRow(const char* label, const QualityMetrics& m) {
  std::printf("%-10s %10.3f %13.3f %10.3f %12.3f %10.3f %8.3f %8.2fs\n", label, m.coherence, m.completeness,
              m.histogram, m.periodicity, m.sharpness, m.lattice, m.seconds);
}

Command registerEvalCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand("eval",
                                 "Measure a synthesized image or volume against its exemplar.\n"
                                 "coherence: RMS distance of output patches to their nearest exemplar patch (lower = "
                                 "no invented content); completeness: the same from exemplar to output (lower = "
                                 "nothing of the exemplar missing); histogram: mean per-channel Wasserstein-1 "
                                 "distance; periodicity: share of sampled patches repeated at the most common offset "
                                 "(tiling scores high, good synthesis near 0); lattice: strongest autocorrelation peak "
                                 "of the luminance detail away from the origin (a shifted repeat of the same content, "
                                 "as in a tiling or a grid of copies, scores high; noise and good synthesis near 0); "
                                 "sharpness: mean gradient magnitude over the exemplar's (1 = as crisp, lower = "
                                 "blurrier). Colors on 0..255.");
  struct Args {
    std::string exemplar, output;
    MetricOptions options;
  };
  auto args = std::make_shared<Args>();
  inputFiles(sub->add_option("EXEMPLAR", args->exemplar, "The exemplar image"))->required();
  inputFiles(
      sub->add_option("OUTPUT", args->output, "A synthesized image, or a volume (" + readableVolumeExtensions() + ")"))
      ->required();
  sub->add_option("--patch", args->options.patchSize, "Patch size (odd) for coherence, completeness and periodicity")
      ->capture_default_str()
      ->check(integerIn(1, 63));
  sub->add_option("--periodicity-samples", args->options.periodicitySamples, "Output patches sampled for periodicity")
      ->capture_default_str()
      ->check(integerIn(1, 100000));
  sub->add_option("--slices", args->options.slicesPerAxis, "Volumes: slices evaluated per axis")
      ->capture_default_str()
      ->check(integerIn(1, 4096));
  const ParameterSources sources = {
      {"patchSize", fromFlag("--patch")},           {"periodicitySamples", fromFlag("--periodicity-samples")},
      {"slicesPerAxis", fromFlag("--slices")},      {"exemplar", fromFile(args->exemplar)},
      {"output", fromFile(args->output)},           {"volume", fromFile(args->output)},
      {"histogramDistance", fromFile(args->output)}};

  return {sub,
          [sub, args, &globals] {
            const bool volume = fileKind(args->output) == FileKind::Volume;
            rejectFlagsOutsideMode(*sub, {{"--slices", {"volume OUTPUTs"}}}, volume ? "volume OUTPUTs" : "",
                                   "when OUTPUT is an image");
            args->options.seed = globals.seed;
            Image exemplar = readImage(args->exemplar);
            json report = {{"exemplar", args->exemplar}, {"output", args->output}, {"patch", args->options.patchSize}};
            if (volume) {
              VolumeQuality q = evaluateVolume(exemplar, readVolume(args->output), args->options);
              report["x"] = toJson(q.axis[0]);
              report["y"] = toJson(q.axis[1]);
              report["z"] = toJson(q.axis[2]);
              report["mean"] = toJson(q.mean);
              if (globals.json) return printJson(report);
              std::printf("%-10s %10s %13s %10s %12s %10s %8s %9s\n", "slices", "coherence", "completeness",
                          "histogram", "periodicity", "sharpness", "lattice", "time");
              const char* names[3] = {"x-normal", "y-normal", "z-normal"};
              for (int a = 0; a < 3; ++a) printRow(names[a], q.axis[a]);
              printRow("mean", q.mean);
              return;
            }
            QualityMetrics m = evaluateImage(exemplar, readImage(args->output), args->options);
            report["metrics"] = toJson(m);
            if (globals.json) return printJson(report);
            std::printf("coherence    %8.3f   (lower is better)\n", m.coherence);
            std::printf("completeness %8.3f   (lower is better)\n", m.completeness);
            std::printf("histogram    %8.3f   (lower is better)\n", m.histogram);
            std::printf("periodicity  %8.3f   (lower is better; tiling scores high)\n", m.periodicity);
            std::printf("lattice      %8.3f   (lower is better; a shifted repeat of the same content scores high)\n",
                        m.lattice);
            std::printf("sharpness    %8.3f   (1 = as crisp as the exemplar; lower is blurrier)\n", m.sharpness);
            std::printf("time         %8.2fs\n", m.seconds);
          },
          sources, "--patch (or give smaller images)"};
}

}  // namespace texsynth::cli
