// texsynth eval EXEMPLAR OUTPUT: coherence (mean and tail), completeness, histogram, periodicity, lattice and
// sharpness of a result; for a mesh with vertex colors, surface coherence (plain and
// rotation-invariant), completeness, flatness and histogram.
#include <cstdio>

#include "cli_common.h"
#include "mode_flags.h"
#include "number_checks.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/io/color_values.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"
#include "texsynth/surface/surface_quality.h"
#include "texsynth/surface/tangent_field.h"

namespace texsynth::cli {

using nlohmann::json;

static json toJson(const QualityMetrics& m) {
  json metrics = metricsJson(m);
  metrics["seconds"] = m.seconds;
  return metrics;
}

// One row of the volume table; lattice and the coherence tail come after sharpness so that
// scripts reading the first five metric columns keep working.
static void printRow(const char* label, const QualityMetrics& m) {
  std::printf("%-10s %10.3f %13.3f %10.3f %12.3f %10.3f %8.3f %14.3f %8.2fs\n", label, m.coherence, m.completeness,
              m.histogram, m.periodicity, m.sharpness, m.lattice, m.coherenceTail, m.seconds);
}

// The surface measure of a mesh with vertex colors, oriented as surface synthesis orients its
// texture by default: the smooth field following world +Y is the exemplar's up direction b, and
// the patches' x axis is t = b x n.
static SurfaceQuality evaluateMesh(const Image& exemplar, const std::string& path,
                                   const SurfaceQualityOptions& options) {
  Mesh mesh = readMesh(path);
  if (mesh.colors.empty())
    throw InputError(path, "has no vertex colors: eval measures a mesh by the texture in its vertex colors");
  try {
    std::vector<Vec3f> tangents = smoothTangentField(mesh);
    for (std::size_t v = 0; v < tangents.size(); ++v) tangents[v] = tangents[v].cross(mesh.normals[v]).normalized();
    return evaluateSurface(exemplar, mesh, tangents, options);
  } catch (const InputError& e) {
    if (e.file() == "mesh") throw InputError(path, e.problem());  // the library's name for it
    throw;
  }
}

Command registerEvalCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub =
      app.add_subcommand("eval",
                         "Measure a synthesized image or volume against its exemplar.\n"
                         "coherence: RMS distance of output patches to their nearest exemplar patch (lower = "
                         "no invented content); coherence_p90: its 90th percentile over the patches, the "
                         "worst tenth, where seams show; completeness: the same from exemplar to output (lower = "
                         "nothing of the exemplar missing); histogram: mean per-channel Wasserstein-1 "
                         "distance; periodicity: share of sampled patches repeated at the most common offset "
                         "(tiling scores high, good synthesis near 0); lattice: strongest autocorrelation peak "
                         "of the luminance detail away from the origin (a shifted repeat of the same content, "
                         "as in a tiling or a grid of copies, scores high; noise and good synthesis near 0); "
                         "sharpness: mean gradient magnitude over the exemplar's (1 = as crisp, lower = "
                         "blurrier). Colors on 0..255.\n"
                         "A mesh with vertex colors (a retiled one, as texsynth surface writes, one vertex per "
                         "texture pixel) gets the surface measures: coherence of the patches resampled around "
                         "sampled vertices along the default surface orientation (exemplar up = world +Y), "
                         "rotation-invariant coherence (each patch at the best of its 8 rotations and mirrors: "
                         "for textures whose orientation on the surface is unknown, such as solids), "
                         "completeness (from exemplar patches to their nearest sampled surface patch; with "
                         "fewer samples than exemplar patches it stays above 0 even for a perfect copy), "
                         "flatness (the share of sampled patches flatter than the exemplar's 10th-percentile "
                         "patch, minus 0.1: about 0 for a faithful texture, may dip slightly below; 0.9 for "
                         "one color), and the histogram distance of the vertex colors.");
  struct Args {
    std::string exemplar, output;
    MetricOptions options;
    SurfaceQualityOptions surface;
  };
  auto args = std::make_shared<Args>();
  inputFiles(sub->add_option("EXEMPLAR", args->exemplar, "The exemplar image"))->required();
  inputFiles(sub->add_option("OUTPUT", args->output,
                             "A synthesized image, a volume (" + readableVolumeExtensions() +
                                 "), or a mesh with vertex colors (" + readableMeshExtensions() + ")"))
      ->required();
  sub->add_option("--patch", args->options.patchSize,
                  "Patch size (odd) for coherence, completeness and periodicity; at most the shortest side of the "
                  "images (of a volume's slices)")
      ->capture_default_str()
      ->check(integerIn(1, 63));
  sub->add_option("--periodicity-samples", args->options.periodicitySamples, "Output patches sampled for periodicity")
      ->capture_default_str()
      ->check(integerIn(1, 100000));
  sub->add_option("--slices", args->options.slicesPerAxis, "Volumes: slices evaluated per axis")
      ->capture_default_str()
      ->check(integerIn(1, 4096));
  sub->add_option("--samples", args->surface.samples, "Meshes: vertices evaluated (0 = all)")
      ->capture_default_str()
      ->check(integerIn(0, 100000000));
  const ParameterSources sources = {{"patchSize", fromFlag("--patch")},
                                    {"periodicitySamples", fromFlag("--periodicity-samples")},
                                    {"slicesPerAxis", fromFlag("--slices")},
                                    {"exemplar", fromFile(args->exemplar)},
                                    {"output", fromFile(args->output)},
                                    {"volume", fromFile(args->output)},
                                    {"histogramDistance", fromFile(args->output)},
                                    {"samples", fromFlag("--samples")}};

  return {sub,
          [sub, args, &globals] {
            const FileKind kind = fileKind(args->output);
            const bool volume = kind == FileKind::Volume, mesh = kind == FileKind::Mesh;
            const char* mode = volume ? "volume OUTPUTs" : mesh ? "mesh OUTPUTs" : "image OUTPUTs";
            const char* phrase = volume ? "when OUTPUT is a volume"
                                 : mesh ? "when OUTPUT is a mesh"
                                        : "when OUTPUT is an image";
            rejectFlagsOutsideMode(*sub,
                                   {{"--slices", {"volume OUTPUTs"}},
                                    {"--samples", {"mesh OUTPUTs"}},
                                    {"--periodicity-samples", {"image OUTPUTs", "volume OUTPUTs"}}},
                                   mode, phrase);
            args->options.seed = globals.seed;
            // Colour images: a NaN or 1e30 in an EXR is the file's fault, not a metric to report.
            Image exemplar = readColorImage(args->exemplar);
            json report = {{"exemplar", args->exemplar}, {"output", args->output}, {"patch", args->options.patchSize}};
            if (mesh) {
              args->surface.patchSize = args->options.patchSize;
              args->surface.seed = globals.seed;
              const SurfaceQuality q = evaluateMesh(exemplar, args->output, args->surface);
              report["surface"] = {{"coherence", q.coherence},
                                   {"rotation_invariant", q.rotationInvariant},
                                   {"completeness", q.completeness},
                                   {"flatness", q.flatness},
                                   {"histogram", q.histogram},
                                   {"evaluated", q.evaluated},
                                   {"near_border", q.nearBorder},
                                   {"spacing", q.spacing},
                                   {"seconds", q.seconds}};
              if (globals.json) return printJson(report);
              std::printf("coherence           %8.3f   (lower is better)\n", q.coherence);
              std::printf("rotation-invariant  %8.3f   (lower is better; each patch at its best rotation or mirror)\n",
                          q.rotationInvariant);
              std::printf("completeness        %8.3f   (lower is better; exemplar patches to their nearest)\n",
                          q.completeness);
              std::printf("flatness            %8.3f   (lower is better; ~0 like the exemplar, 0.9 one color)\n",
                          q.flatness);
              std::printf("histogram           %8.3f   (lower is better)\n", q.histogram);
              std::printf("vertices            %8d   evaluated (%d near a border left out)\n", q.evaluated,
                          q.nearBorder);
              std::printf("time                %8.2fs\n", q.seconds);
              return;
            }
            if (volume) {
              auto progress = makeProgress(globals);  // many slices with large patches take a while
              VolumeQuality q = evaluateVolume(exemplar, readVolume(args->output), args->options, *progress);
              report["x"] = toJson(q.axis[0]);
              report["y"] = toJson(q.axis[1]);
              report["z"] = toJson(q.axis[2]);
              report["mean"] = toJson(q.mean);
              if (globals.json) return printJson(report);
              std::printf("%-10s %10s %13s %10s %12s %10s %8s %14s %9s\n", "slices", "coherence", "completeness",
                          "histogram", "periodicity", "sharpness", "lattice", "coherence_p90", "time");
              const char* names[3] = {"x-normal", "y-normal", "z-normal"};
              for (int a = 0; a < 3; ++a) printRow(names[a], q.axis[a]);
              printRow("mean", q.mean);
              return;
            }
            QualityMetrics m = evaluateImage(exemplar, readColorImage(args->output), args->options);
            report["metrics"] = toJson(m);
            if (globals.json) return printJson(report);
            std::printf("coherence    %8.3f   (lower is better)\n", m.coherence);
            std::printf("  90th pct   %8.3f   (the worst tenth of patches, where seams show; lower is better)\n",
                        m.coherenceTail);
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
