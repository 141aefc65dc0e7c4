#pragma once
// The flags of `texsynth image`, and the pixel-based methods (parallel, optimize) and
// --apply-coords that cmd_image.cpp dispatches to (image_pixel_methods.cpp).
#include <nlohmann/json.hpp>
#include <string>

#include "cli_common.h"
#include "texsynth/core/image.h"

namespace texsynth::cli {

struct ImageArgs {
  std::string exemplar, output, method = "tile-deform", size = "512", window;
  std::string tileable = "auto", saveTileable, coords, applyCoords;
  float seamThreshold = 1.5f;
  // tile-deform
  std::string cell = "0", lambda = "0.35", directions = "both";
  float clamp = 0.45f, noiseFrequency = 0.6f;
  // tile-blend
  float tileSize = 0, blendExponent = 2.0f;
  // parallel and optimize; empty / -1 = the method's default
  std::string neighborhoods;
  int levels = -1, similarCount = -1;
  // parallel
  int passes = 2, subpasses = 2;
  std::string jitter;
  float footprint = -1;  // -1 = the library's default
  // optimize
  std::string solver = "discrete";
  int iterations = -1;                                     // -1 = the library's default
  float coverage = -1, voteExponent = -1, seamBlend = -1;  // -1 = the library's default
  std::string start = "parallel";
};

// Lefebvre & Hoppe 2005 over the window (x, y, width, height); writes --coords if asked.
Image synthesizeParallelWindow(const Image& exemplar, const ImageArgs& args, const Window& window,
                               const GlobalOptions& globals, nlohmann::json& report);

// Texture optimization (discrete or least squares) of a width x height image at the origin.
Image synthesizeOptimized(const Image& exemplar, const ImageArgs& args, int width, int height,
                          const GlobalOptions& globals, nlohmann::json& report);

// --apply-coords: the colors of `map` at the source coordinates stored in args.applyCoords.
Image applyCoordinates(const Image& map, const ImageArgs& args, nlohmann::json& report);

}  // namespace texsynth::cli
