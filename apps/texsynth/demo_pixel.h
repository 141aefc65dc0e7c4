#pragma once
// The demo's 2D section: parallel synthesis (Lefebvre & Hoppe 2005, from a random start) and
// texture optimization (discrete solver, from the parallel result) of the exemplar at 256^2,
// scored by `texsynth eval` next to the plain-tiling baseline.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "texsynth/core/image.h"
#include "texsynth/exemplar/analysis.h"

namespace texsynth::cli {

// A number for the demo's report: three decimals are plenty for times and metrics.
std::string fixed3(double value);

// Writes pixel_synthesis.png (exemplar | parallel | optimize) through `out` and returns the
// report's "pixel" section; `analysis` is the exemplar's default analysis (parallel's), the
// optimizer's go through the cache in `cacheDirectory`.
nlohmann::json demoPixelSynthesis(const Image& exemplar, const ExemplarAnalysis& analysis, std::uint64_t seed,
                                  const std::string& cacheDirectory,
                                  const std::function<std::string(const std::string&)>& out);

// That section, with the tiling baseline `tiling` (a metricsJson row), as markdown.
std::string pixelMarkdown(const nlohmann::json& pixel, const nlohmann::json& tiling);

}  // namespace texsynth::cli
