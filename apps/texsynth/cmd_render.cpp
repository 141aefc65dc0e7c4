// texsynth render MESH|VOLUME|SOLID.tsgs -o view.png: a shaded picture of a mesh, or a slice montage of a
// volume or a gradient solid.
#include "cli_common.h"
#include "mode_flags.h"
#include "number_checks.h"
#include "texsynth/core/memory_budget.h"
#include "texsynth/core/volume.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"
#include "texsynth/render/render_mesh.h"
#include "texsynth/render/slice_montage.h"

namespace texsynth::cli {

Command registerRenderCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand("render",
                                 "Render a mesh (per-vertex colors if it has them, Lambert + ambient, camera fitted "
                                 "automatically), or a volume or gradient solid (.tsgs; slices normal to x, y and z), "
                                 "to an image");
  struct Args {
    std::string input, output, size = "768", up;
    float yaw = 30, pitch = 20;
    int views = 1, supersample = 2;
  };
  auto args = std::make_shared<Args>();
  inputFiles(sub->add_option("INPUT", args->input,
                             "Mesh (" + readableMeshExtensions() + "), volume (" + readableVolumeExtensions() +
                                 ") or gradient solid (.tsgs)"))
      ->required();
  outputFiles(sub->add_option("-o,--output", args->output, "Output image (.png .jpg .exr ...)"))->required();
  sub->add_option("--size", args->size, "Image size of one view, WxH or N")->capture_default_str();
  sub->add_option("--yaw", args->yaw, "Camera yaw around the model's up axis (--up), degrees")
      ->capture_default_str()
      ->check(finiteIn(-360, 360));
  sub->add_option("--pitch", args->pitch, "Camera elevation, degrees")->capture_default_str()->check(finiteIn(-90, 90));
  sub->add_option("--views", args->views, "Views side by side (1 = the given yaw; 4 = yaw, yaw+90, ...)")
      ->capture_default_str()
      ->check(integerIn(1, 4));
  sub->add_option("--supersample", args->supersample, "Samples per pixel side (anti-aliasing)")
      ->capture_default_str()
      ->check(integerIn(1, 16));
  sub->add_option("--up", args->up, kViewUpHelp);
  // The camera's flags do nothing for a volume's slice montage.
  const std::vector<ModeFlag> meshOnly = {{"--size", {"meshes"}},        {"--yaw", {"meshes"}},
                                          {"--pitch", {"meshes"}},       {"--views", {"meshes"}},
                                          {"--supersample", {"meshes"}}, {"--up", {"meshes"}}};
  const ParameterSources sources = {{"width", fromFlag("--size")},
                                    {"height", fromFlag("--size")},
                                    {"supersample", fromFlag("--supersample")},
                                    {"yawDegrees", fromFlag("--yaw")},
                                    {"pitchDegrees", fromFlag("--pitch")},
                                    {"up", fromFlag("--up")},
                                    {"mesh", fromFile(args->input)},
                                    {"bounds", fromFile(args->input)},
                                    {"box", fromFile(args->input)},
                                    {"volume", fromFile(args->input)},
                                    {"scale", fromFile(args->input)}};

  return {sub,
          [sub, meshOnly, args, &globals] {
            const FileKind kind = fileKind(args->input);
            rejectFlagsOutsideMode(*sub, meshOnly,
                                   kind == FileKind::Volume || kind == FileKind::GradientSolid ? "" : "meshes",
                                   "for a volume");
            // Check the output format before the work, so a typo costs nothing.
            if (fileKind(args->output) != FileKind::Image)
              throw ParameterError(
                  "--output", "'" + args->output + "' is not an image file name (" + readableImageExtensions() + ")");
            Image picture;
            switch (fileKind(args->input)) {
              case FileKind::Mesh: {
                Size2 size = parseSize(args->size, "--size");
                RenderOptions options;
                options.width = size.width;
                options.height = size.height;
                options.yawDegrees = args->yaw;
                options.pitchDegrees = args->pitch;
                options.supersample = args->supersample;
                if (!args->up.empty()) parseDirection(args->up, "--up");  // a typo costs nothing
                requireMemory(renderMemoryBytes(options, args->views), "--size", "the rendered views");
                Mesh mesh = readMesh(args->input);
                options.up = viewUp(args->up, mesh);
                std::vector<std::pair<float, float>> views;
                for (int v = 0; v < args->views; ++v) views.push_back({args->yaw + 90.0f * v, args->pitch});
                picture = renderViews(mesh, nullptr, views, options);
                break;
              }
              case FileKind::Volume:
                picture = sliceMontage(readVolume(args->input));
                break;
              case FileKind::GradientSolid: {  // its equivalent raster, region boundaries antialiased
                const GradientSolid solid = readGradientSolid(args->input);
                requireMemory(double(solid.voxels.cast<double>().prod()) * solid.channels * 4.0, "INPUT",
                              "the gradient solid's raster");
                GradientEvaluateOptions options;
                options.antialiasVoxels = 1.0f;
                options.detail = true;
                picture = sliceMontage(rasterizeGradientSolid(solid, options));
                break;
              }
              default:
                throw InputError(args->input, "cannot render this file type; give a mesh (" + readableMeshExtensions() +
                                                  "), a volume (" + readableVolumeExtensions() +
                                                  ") or a gradient solid (.tsgs)");
            }
            writeImage(args->output, picture);
            sayWhenCommitted(globals, "wrote " + args->output);
          },
          sources, "--size or --supersample"};
}

}  // namespace texsynth::cli
