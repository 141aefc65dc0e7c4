#pragma once
// The flags of `texsynth solid`, and the lazy method's construction (solid_lazy.cpp).
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.h"
#include "texsynth/core/mesh.h"
#include "texsynth/gradient/gradient_solid.h"
#include "texsynth/solid/lazy_solid.h"
#include "texsynth/solid/solid_texture.h"

namespace texsynth::cli {

struct SolidArgs {
  std::vector<std::string> exemplars;  // EXEMPLAR [YZ_EXEMPLAR ZX_EXEMPLAR]
  std::string method = "tile-deform", mesh, render, stats, stack = "xyz";
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

// --method lazy: one LazySolid on the exemplars (one for all planes, or XY YZ ZX), guided by
// --field or a field designed from --sketch on the mesh if given; with --inner and a mesh, a second one fills
// everything deeper than --shell (a fraction of the mesh's bounding-box diagonal) below the surface. The coarsest level
// is synthesized over all of `box` up front, for every later request to reuse.
struct LazyBuild {
  std::unique_ptr<SolidTexture> texture;
  std::vector<std::pair<std::string, std::shared_ptr<LazySolid>>> parts;  // name, synthesis
};
LazyBuild makeLazySolid(const SolidArgs& args, const Mesh& mesh, const Box3f& box, const SolidPlacement& placement,
                        std::uint64_t seed, nlohmann::json& report, Progress& progress);

// --method gradient with image exemplars: a gradient solid synthesized over `box` at --resolution (§4 of
// gradient-solid-textures), following --field or the field of --sketch, with --inner's exemplar deeper than
// --shell below the mesh's surface.
std::shared_ptr<const GradientSolid> synthesizeGradient(const SolidArgs& args, const Mesh& mesh, const Box3f& box,
                                                        std::uint64_t seed, const GlobalOptions& globals,
                                                        nlohmann::json& report);

// Per-level work of every lazy part, for --stats.
nlohmann::json lazyStats(const LazyBuild& build);

}  // namespace texsynth::cli
