#pragma once
// `texsynth surface`: its flags, and the outputs a run writes (surface_outputs.cpp).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "texsynth/core/mesh.h"
#include "texsynth/core/progress.h"
#include "texsynth/surface/surface_synthesis.h"

namespace texsynth::cli {

struct SurfaceArgs {
  std::string exemplar, mesh, field, sketch, up, render, stats, coords, applyCoords, bake;
  std::vector<std::string> outputs;
  int vertices = 48000, levels = 3, iterations = kSurfaceIterations, renderSize = 768, views = 2, bakeSize = 2048;
  float featureWeight = kSurfaceFeatureWeight;
};

// What a run made: the retiled mesh with colors, and the synthesis behind them.
struct SurfaceResult {
  Mesh colored;                       // no attributes
  std::vector<std::int32_t> sources;  // per vertex of `colored`: exemplar pixel y * width + x
  int exemplarWidth = 0, exemplarHeight = 0;
  const Mesh* uvMesh = nullptr;  // the input mesh, with its "uv" attribute, for --bake
};

// Writes -o, --coords, --render and --bake, in that order; one report entry per file (its name
// and seconds). Progress: one stage, one unit per file (the bake adds its own stage).
nlohmann::json writeSurfaceOutputs(const SurfaceArgs& args, const SurfaceResult& result, Progress& progress);

// Peak bytes of the outputs that grow with a flag (--render-size, --bake-size), checked before any work.
void requireSurfaceOutputMemory(const SurfaceArgs& args);

}  // namespace texsynth::cli
