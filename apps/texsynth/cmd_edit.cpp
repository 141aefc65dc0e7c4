// texsynth edit SOLID.tsgs --strokes S.json --color R,G,B -o OUT.tsgs: instant edit propagation on a
// gradient solid (gradient-solid-textures §4.4): control points only, so a large solid edits at once.
#include <algorithm>
#include <cstdio>
#include <optional>

#include "cli_common.h"
#include "number_checks.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/gradient/gradient_edit.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "texsynth/io/file_kind.h"

namespace texsynth::cli {

namespace {

// "R,G,B" with each in [0,1], or "#rrggbb".
Vec3f parseColor(const std::string& text) {
  if (text.size() == 7 && text[0] == '#') {
    Vec3f color;
    for (int c = 0; c < 3; ++c) {
      const std::string hex = text.substr(1 + 2 * c, 2);
      if (hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
        throw ParameterError("--color", "'" + text + "': give R,G,B in [0,1] or #rrggbb");
      color[c] = float(std::stoi(hex, nullptr, 16)) / 255.0f;
    }
    return color;
  }
  const Vec3f color = parseFloatTriple(text, "--color", false);
  for (int c = 0; c < 3; ++c)
    if (!(color[c] >= 0.0f && color[c] <= 1.0f))
      throw ParameterError("--color", "'" + text + "': each of R,G,B must be in [0,1]");
  return color;
}

}  // namespace

Command registerEditCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "edit",
      "Recolour a gradient solid from a few strokes (instant edit propagation, gradient-solid-textures §4.4): the "
      "stroke voxels' strengths say how strongly to move towards --color, and the edit spreads to voxels near them "
      "in position and colour. Works on the control points only, so even a 512^3-equivalent solid edits in a "
      "fraction of a second.\nStroke format: docs/stroke-format.md.");
  struct Args {
    std::string input, strokes, color, output, stats;
    int centres = EditOptions{}.centres;
    float alpha = EditOptions{}.alpha, beta = EditOptions{}.beta;
  };
  auto args = std::make_shared<Args>();
  inputFiles(sub->add_option("SOLID", args->input, "Gradient solid to edit (.tsgs)"))->required();
  inputFiles(sub->add_option("--strokes", args->strokes, "Stroke file, JSON (docs/stroke-format.md)"))->required();
  sub->add_option("--color", args->color,
                  "Reference colour R,G,B in [0,1] or #rrggbb (default: the stroke file's \"color\")");
  outputFiles(sub->add_option("-o,--output", args->output, "Edited gradient solid to write (.tsgs)"))->required();
  sub->add_option("--centres", args->centres, "RBF centres m drawn from the stroke voxels")
      ->capture_default_str()
      ->check(integerIn(1, 512));
  sub->add_option("--alpha", args->alpha, "Propagation falloff alpha (paper: 1e-4; larger: a more local edit)")
      ->capture_default_str()
      ->check(finiteIn(1e-9, 1));
  sub->add_option("--beta", args->beta, "Weight of position against colour, beta (paper: 0.1)")
      ->capture_default_str()
      ->check(finiteIn(0, 1e6));
  outputFiles(sub->add_option("--stats", args->stats, "Write the report (times, weights) as JSON here"));
  const ParameterSources sources = {{"strokes", fromFile(args->strokes)}, {"solid", fromFile(args->input)},
                                    {"color", fromFlag("--color")},       {"centres", fromFlag("--centres")},
                                    {"alpha", fromFlag("--alpha")},       {"beta", fromFlag("--beta")}};
  return {sub,
          [args, &globals] {
            for (const std::string* file : {&args->input, &args->output})
              if (fileExtension(*file) != kGradientSolidExtension)
                throw ParameterError(file == &args->input ? "SOLID" : "--output",
                                     "'" + *file + "' must end in ." + kGradientSolidExtension);
            std::optional<Vec3f> color;
            if (!args->color.empty()) color = parseColor(args->color);
            const EditStrokeFile strokes = readEditStrokeFile(args->strokes);
            if (!color) color = strokes.color;
            if (!color)
              throw ParameterError("--color", "give the reference colour (--color or \"color\" in the strokes)");
            GradientSolid solid = readGradientSolid(args->input);
            EditOptions options;
            options.color = *color;
            options.centres = args->centres;
            options.alpha = args->alpha;
            options.beta = args->beta;
            options.seed = globals.seed;
            const EditReport report = editGradientSolid(solid, strokes.strokes, options);
            writeGradientSolid(args->output, solid);

            const nlohmann::json out = {{"input", args->input},
                                        {"output", args->output},
                                        {"stroke_voxels", report.strokeVoxels},
                                        {"centres", report.centres},
                                        {"lp_rows", report.lpRows},
                                        {"weights", report.weights},
                                        {"lp_seconds", report.lpSeconds},
                                        {"update_seconds", report.updateSeconds},
                                        {"mean_strength_deviation", report.strengthDeviation},
                                        {"controls", solid.controlCount()}};
            char line[256];
            std::snprintf(line, sizeof line,
                          "wrote %s: %d stroke voxels, %d centres, linear program %.3f s, update %.3f s, mean strength "
                          "deviation %.3f",
                          args->output.c_str(), report.strokeVoxels, report.centres, report.lpSeconds,
                          report.updateSeconds, report.strengthDeviation);
            finishReport(globals, out, args->stats, line);
          },
          sources, ""};
}

}  // namespace texsynth::cli
