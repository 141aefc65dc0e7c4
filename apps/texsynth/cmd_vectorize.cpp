// texsynth vectorize VOLUME [--mask MASK] [--optimize] -o SOLID.tsgs: a voxel solid as a gradient solid
// (gradient-solid-textures §5.2), with its error and size against the voxels.
#include <cstdio>

#include "cli_common.h"
#include "mode_flags.h"
#include "number_checks.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "texsynth/gradient/vectorize.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/volume_io.h"

namespace texsynth::cli {

Command registerVectorizeCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "vectorize",
      "Turn a voxel solid into a gradient solid (.tsgs): a control point every --spacing voxels with a colour and its "
      "three gradients, evaluated by tricubic interpolation at any resolution (gradient-solid-textures §5.2). "
      "First-order fit per control point (eq. 2); --optimize refines every control point against every voxel (eq. "
      "3). With --mask, the two regions keep a sharp boundary (§3.2). Reports the RMS error (0..255), the time and "
      "the file's size against the raw 8-bit volume.\n"
      "Look at the result with `texsynth render SOLID.tsgs` or `texsynth solid SOLID.tsgs --slice z=0.5 -o s.png`.");
  struct Args {
    std::string volume, mask, output, stats;
    bool optimize = false, detail = false;
    int iterations = VectorizeOptions{}.iterations, spacing = VectorizeOptions{}.spacing;
  };
  auto args = std::make_shared<Args>();
  inputFiles(sub->add_option("VOLUME", args->volume, "Voxel solid (" + readableVolumeExtensions() + "), gray or RGB"))
      ->required();
  inputFiles(sub->add_option("--mask", args->mask,
                             "Binary mask volume of the same size (> 0.5 inside): separate the two regions"));
  outputFiles(sub->add_option("-o,--output", args->output, "Gradient solid to write (.tsgs)"))->required();
  sub->add_flag("--optimize", args->optimize,
                "Refine the control points against every voxel (eq. 3; paper Table 1 'w/ opt.'): lower error, a few "
                "times the time");
  sub->add_option("--iterations", args->iterations, "--optimize: conjugate-gradient iterations")
      ->capture_default_str()
      ->check(integerIn(1, 1000));
  sub->add_option("--spacing", args->spacing, "Voxels between control points d (paper: 4; larger: smaller files)")
      ->capture_default_str()
      ->check(integerIn(1, 64));
  sub->add_flag("--detail", args->detail,
                "Also store the residual's standard deviation (§5.4), so magnified views keep the grain "
                "(`solid --detail on`)");
  outputFiles(sub->add_option("--stats", args->stats, "Write the report (error, times, sizes) as JSON here"));
  const ParameterSources sources = {{"volume", fromFile(args->volume)},
                                    {"mask", fromFile(args->mask)},
                                    {"spacing", fromFlag("--spacing")},
                                    {"iterations", fromFlag("--iterations")}};
  return {sub,
          [sub, args, &globals] {
            rejectFlagsOutsideMode(*sub, {{"--iterations", {"--optimize"}}}, args->optimize ? "--optimize" : "",
                                   "without --optimize");
            if (fileExtension(args->output) != kGradientSolidExtension)
              throw ParameterError("--output", "'" + args->output + "' must end in ." + kGradientSolidExtension);
            const Volume volume = readVolume(args->volume);
            const Volume mask = args->mask.empty() ? Volume() : readVolume(args->mask);
            // The colours, the two sides' dilated copies and the distances, as floats.
            requireMemory(double(volume.voxelCount()) * 4.0 * (3 + (mask.empty() ? 1 : 8)), "VOLUME",
                          "vectorizing " + std::to_string(volume.voxelCount()) + " voxels");
            VectorizeOptions options;
            options.optimize = args->optimize;
            options.iterations = args->iterations;
            options.spacing = args->spacing;
            options.detail = args->detail;
            auto progress = makeProgress(globals);
            VectorizeReport report;
            const GradientSolid solid = vectorizeVolume(volume, mask, options, &report, *progress);
            writeGradientSolid(args->output, solid);

            const double bytes = double(gradientSolidFileBytes(solid)), raw = double(rawVolumeBytes(solid));
            nlohmann::json out = {{"input", args->volume},
                                  {"output", args->output},
                                  {"voxels", {solid.voxels.x(), solid.voxels.y(), solid.voxels.z()}},
                                  {"controls", {solid.controls.x(), solid.controls.y(), solid.controls.z()}},
                                  {"spacing", solid.spacing},
                                  {"channels", solid.channels},
                                  {"regions", solid.hasRegions()},
                                  {"boundary_controls", report.boundaryControls},
                                  {"detail", solid.hasDetail()},
                                  {"optimize", args->optimize},
                                  {"rms_error_255", report.rms},
                                  {"fit_seconds", report.fitSeconds},
                                  {"optimize_seconds", report.optimizeSeconds},
                                  {"total_seconds", report.totalSeconds},
                                  {"file_bytes", bytes},
                                  {"raw_volume_bytes", raw},
                                  {"percent_of_raw", 100.0 * bytes / raw}};
            char line[256];
            std::snprintf(line, sizeof line,
                          "wrote %s: RMS error %.2f (0..255), %.2f s, %.0f bytes = %.1f%% of the raw volume",
                          args->output.c_str(), report.rms, report.totalSeconds, bytes, 100.0 * bytes / raw);
            finishReport(globals, out, args->stats, line);
          },
          sources, ""};
}

}  // namespace texsynth::cli
