#pragma once
// The demo's gradient-solid section (gradient-solid-textures §4.4, §5.2): a small tile-deform solid
// of the exemplar, vectorized, magnified and edited, kept to a few seconds.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "texsynth/core/image.h"

namespace texsynth::cli {

// Writes gradient_magnified.png, gradient_edit.png and gradient_solid.tsgs through `out` (a file
// name -> its path in the output directory) and returns the report's "gradient" section.
nlohmann::json demoGradientSolids(const Image& exemplar, std::uint64_t seed,
                                  const std::function<std::string(const std::string&)>& out);

// That section as markdown.
std::string gradientMarkdown(const nlohmann::json& gradient);

}  // namespace texsynth::cli
