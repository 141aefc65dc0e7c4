// texsynth field MESH --sketch S.json -o FIELD: a rotation field designed from sketch curves
// (sketch-guided solid texturing §3), optionally rendered as axis glyphs.
#include <cmath>
#include <cstdio>

#include "cli_common.h"
#include "mode_flags.h"
#include "number_checks.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/field/field_designer.h"
#include "texsynth/field/field_io.h"
#include "texsynth/field/field_render.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth::cli {

namespace {

// "z=0.5" -> (2, 0.5); "none" -> (-1, 0).
std::pair<int, float> parseCut(const std::string& text) {
  if (text == "none") return {-1, 0.0f};
  return parseAxisPosition(text, "--cut", true);
}

// The glyph render's flags do nothing without --render.
const std::vector<ModeFlag> kFieldModeFlags = {{"--render-size", {"--render"}},
                                               {"--views", {"--render"}},
                                               {"--glyphs", {"--render"}},
                                               {"--cut", {"--render"}},
                                               {"--up", {"--render"}}};

}  // namespace

Command registerFieldCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "field",
      "Design a rotation field from sketch curves (harmonic quaternion interpolation, sketch-guided solid "
      "texturing §3) on a grid around MESH; write it as a .tsfield file and optionally render it as glyphs.\n"
      "Sketch format: docs/sketch-format.md. Examples: examples/sketches/*.json");
  struct Args {
    std::string mesh, sketch, output, render, cut = "z=0.5", up;
    int grid = 24, renderSize = 512, views = 1, glyphs = 14;
    float margin = 0.05f, snap = 0.03f;
    double weight = 100;
  };
  auto args = std::make_shared<Args>();
  inputFiles(sub->add_option("MESH", args->mesh, "Mesh the field covers (" + readableMeshExtensions() + ")"))
      ->required();
  inputFiles(sub->add_option("--sketch", args->sketch, "Sketch curves, JSON (docs/sketch-format.md)"))->required();
  outputFiles(sub->add_option("-o,--output", args->output, "Field file to write (.tsfield)"))->required();
  sub->add_option("--grid", args->grid, "Grid cells along the bounding box's shortest side (paper: 20-30)")
      ->capture_default_str()
      ->check(integerIn(2, 512));
  sub->add_option("--margin", args->margin, "Space around the mesh, fraction of its longest side")
      ->capture_default_str()
      ->check(finiteIn(0, 1));
  sub->add_option("--weight", args->weight,
                  "Constraint weight w of eq. 2 (paper: 100; below 1 curves barely pin the field, above 1e4 the "
                  "solver stops converging)")
      ->capture_default_str()
      ->check(finiteIn(kMinConstraintWeight, kMaxConstraintWeight));
  sub->add_option("--snap-tolerance", args->snap,
                  "Largest distance of a sketch point from the surface (or its plane), fraction of the mesh diagonal")
      ->capture_default_str()
      ->check(finiteIn(1e-4, 1));
  outputFiles(sub->add_option("--render", args->render,
                              "Also render glyphs: the mesh, curves (yellow), x/y/z axes (red/green/blue)"));
  sub->add_option("--render-size", args->renderSize, "Pixel size of each rendered view")
      ->capture_default_str()
      ->check(integerIn(16, 4096));
  sub->add_option("--views", args->views, "Surface views in the render (yaw steps of 90 degrees)")
      ->capture_default_str()
      ->check(integerIn(0, 4));
  sub->add_option("--glyphs", args->glyphs, "Glyphs across the mesh's longest side")
      ->capture_default_str()
      ->check(integerIn(2, 200));
  sub->add_option("--cut", args->cut, "Cut view: AXIS=FRACTION of the mesh extent (removes the +AXIS side), or none")
      ->capture_default_str();
  sub->add_option("--up", args->up, "With --render: " + kViewUpHelp);

  const ParameterSources sources = {
      {"shortestCells", fromFlag("--grid")},   {"margin", fromFlag("--margin")},
      {"weight", fromFlag("--weight")},        {"snapTolerance", fromFlag("--snap-tolerance")},
      {"glyphsAcross", fromFlag("--glyphs")},  {"views", fromFlag("--views")},
      {"cutAxis", fromFlag("--cut")},          {"cutPosition", fromFlag("--cut")},
      {"width", fromFlag("--render-size")},    {"height", fromFlag("--render-size")},
      {"mesh", fromFile(args->mesh)},          {"bounds", fromFile(args->mesh)},
      {"box", fromFile(args->mesh)},           {"axis", fromFile(args->sketch)},
      {"positions", fromFile(args->sketch)},   {"rotations", fromFile(args->sketch)},
      {"constraints", fromFile(args->sketch)}, {"normalAxis", fromFile(args->sketch)},
      {"scales", fromFile(args->sketch)},      {"scalePoints", fromFile(args->sketch)}};
  return {sub,
          [sub, args, &globals] {
            rejectFlagsOutsideMode(*sub, kFieldModeFlags, args->render.empty() ? "" : "--render", "without --render");
            FieldDesignOptions options;
            options.grid.shortestCells = args->grid;
            options.grid.margin = args->margin;
            options.solver.weight = args->weight;
            options.snapTolerance = args->snap;
            validateFieldDesignOptions(options);  // before any file is read, so a typo costs nothing
            if (fileExtension(args->output) != "tsfield")
              throw ParameterError("--output", "'" + args->output + "' must end in .tsfield");
            FieldRenderOptions renderOptions;
            if (!args->render.empty()) {
              if (fileKind(args->render) != FileKind::Image)
                throw ParameterError(
                    "--render", "'" + args->render + "' is not an image file name (" + readableImageExtensions() + ")");
              auto [axis, fraction] = parseCut(args->cut);
              renderOptions.showCut = axis >= 0;
              if (axis >= 0) renderOptions.cutAxis = axis, renderOptions.cutPosition = fraction;
              if (args->views == 0 && axis < 0)
                throw ParameterError("--views", "0 views and --cut none render nothing");
              renderOptions.render.width = renderOptions.render.height = args->renderSize;
              renderOptions.glyphsAcross = args->glyphs;
              if (!args->up.empty()) parseDirection(args->up, "--up");
              renderOptions.views.clear();
              for (int v = 0; v < args->views; ++v) renderOptions.views.push_back({30.0f + 90.0f * v, 20.0f});
              requireMemory(renderMemoryBytes(renderOptions.render, args->views + (axis >= 0 ? 1 : 0)), "--render-size",
                            "the rendered views");
            }

            Mesh mesh = readMesh(args->mesh);
            if (!args->render.empty()) renderOptions.render.up = viewUp(args->up, mesh);
            Sketch sketch = readSketch(args->sketch);
            auto progress = makeProgress(globals);
            FieldDesign design = designField(mesh, sketch, options, *progress, args->sketch);
            FieldFile file{design.rotations, design.scales, !sketch.scalePoints.empty()};
            writeField(args->output, file);

            nlohmann::json report;
            const FieldGrid& grid = design.rotations.grid();
            report["grid_nodes"] = {grid.nodes.x(), grid.nodes.y(), grid.nodes.z()};
            report["spacing"] = grid.spacing;
            report["curves"] = nlohmann::json::array();
            for (std::size_t i = 0; i < design.updates.size(); ++i) {
              const CurveUpdate& u = design.updates[i];
              report["curves"].push_back({{"nodes", u.constrainedNodes},
                                          {"cg_iterations", u.solve.iterations},
                                          {"converged", u.solve.converged},
                                          {"milliseconds", 1000 * u.seconds}});
              say(globals, "curve " + std::to_string(i + 1) + ": " + std::to_string(u.constrainedNodes) + " nodes, " +
                               std::to_string(u.solve.iterations) + " CG iterations, " +
                               std::to_string(int(std::lround(1000 * u.seconds))) + " ms");
            }
            sayWhenCommitted(globals, "wrote " + args->output + " (" + std::to_string(grid.nodes.x()) + "x" +
                                          std::to_string(grid.nodes.y()) + "x" + std::to_string(grid.nodes.z()) +
                                          " nodes)");
            if (!args->render.empty()) {
              std::vector<std::vector<Vec3f>> curves;
              for (const auto& samples : design.curveSamples) {
                curves.emplace_back();
                for (const CurveSample& s : samples) curves.back().push_back(s.position);
              }
              writeImage(args->render, renderFieldGlyphs(mesh, design.rotations, curves, renderOptions));
              sayWhenCommitted(globals, "wrote " + args->render);
              report["render"] = args->render;
            }
            report["output"] = args->output;
            if (globals.json) printJsonWhenCommitted(report);
          },
          sources, "--grid or --render-size"};
}

}  // namespace texsynth::cli
