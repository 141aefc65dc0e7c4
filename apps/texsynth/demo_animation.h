#pragma once
// The demo's animation section: the exemplar flowing around a vortex (`texsynth animate`), at the
// default lambda against independent frames and pure advection, timed and scored.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "texsynth/core/image.h"

namespace texsynth::cli {

// Writes animation_frames.png (a filmstrip of the default lambda's frames), animation_lambdas.png
// (the last frame of each lambda) and animation.gif when ffmpeg is there, through `out`; returns
// the report's "animation" section.
nlohmann::json demoAnimation(const Image& exemplar, const std::string& exemplarName, std::uint64_t seed,
                             const std::string& cacheDirectory,
                             const std::function<std::string(const std::string&)>& out);

// That section as markdown.
std::string animationMarkdown(const nlohmann::json& animation);

}  // namespace texsynth::cli
