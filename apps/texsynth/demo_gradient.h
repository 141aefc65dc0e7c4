#pragma once
// The demo's gradient-solid section (gradient-solid-textures §4, §4.4, §5.2): a small tile-deform solid
// of the exemplar, vectorized, magnified and edited, and a small solid synthesized from the exemplar directly,
// kept to a few seconds.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "texsynth/core/image.h"

namespace texsynth::cli {

// Writes gradient_magnified.png, gradient_edit.png, gradient_solid.tsgs and gradient_synthesized.png through
// `out` (a file name -> its path in the output directory) and returns the report's "gradient" section. The
// synthesis's exemplar analysis goes through the cache in `cacheDirectory`.
nlohmann::json demoGradientSolids(const Image& exemplar, std::uint64_t seed, const std::string& cacheDirectory,
                                  const std::function<std::string(const std::string&)>& out);

// That section as markdown.
std::string gradientMarkdown(const nlohmann::json& gradient);

}  // namespace texsynth::cli
