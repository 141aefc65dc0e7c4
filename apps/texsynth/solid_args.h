#pragma once
// The flags of `texsynth solid`, and how they become a solid (the library's factory; solid_lazy.cpp and
// solid_gradient.cpp for the methods with more to read).
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.h"
#include "texsynth/core/mesh.h"
#include "texsynth/gradient/gradient_solid.h"
#include "texsynth/solid/solid_factory.h"

namespace texsynth::cli {

struct SolidArgs {
  std::vector<std::string> exemplars;  // EXEMPLAR [YZ_EXEMPLAR ZX_EXEMPLAR]
  std::string method = "tile-deform", mesh, render, stats, stack = "xyz", up;
  std::vector<std::string> outputs, slices;
  int resolution = 128, renderSize = 768, views = 2, surface = 0;
  float tiles = 2.0f, sharpness = 4.0f;
  bool floatVolume = false;
  // tile-deform
  std::string cell = "0", lambda = "0.4";
  float clamp = 0.45f, noiseScale = 2.5f;
  // tile-blend
  float tileSize = 0, blendExponent = 2.0f;
  // lazy
  std::string field, sketch, inner, cut;
  std::vector<std::string> masks;
  int levels = 0, passes = 1, coarsestPasses = 3, gridCell = 12, subpasses = 1, candidates = 6;
  std::string colorRule = "medoid";
  bool dualGrid = false;
  float shell = 0.05f;
  // gradient: synthesis from images, or a finished solid (.tsgs input)
  std::string detail = "on";
  int iterations = 3, checkPoints = 3, matchedSlices = 3, clusters = 12;
  bool crossbar = true, regions = true, optimize = false;
};

// --method lazy: the recipe's lazy part from the flags: options, --mask, the field of --field or of --sketch on the
// mesh, and --inner below --shell.
void fillLazyRecipe(const SolidArgs& args, const Mesh& mesh, SolidRecipe& recipe, nlohmann::json& report);

// --method gradient with image exemplars: a gradient solid synthesized over `box` at --resolution (§4 of
// gradient-solid-textures), following --field or the field of --sketch, with --inner's exemplar deeper than
// --shell below the mesh's surface.
std::shared_ptr<const GradientSolid> synthesizeGradient(const SolidArgs& args, const Mesh& mesh, const Box3f& box,
                                                        std::uint64_t seed, const GlobalOptions& globals,
                                                        nlohmann::json& report);

// Per-level work of every lazy part, for --stats.
nlohmann::json lazyStats(const SolidBuild& build);

}  // namespace texsynth::cli
