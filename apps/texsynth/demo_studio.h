#pragma once
// The demo's studio section: `texsynth studio`'s server started in-process on a free loopback port
// and driven through its HTTP API as the page drives it (a sketch curve, a textured preview, a cut),
// timed; the cut-open model it answers is rendered.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth::cli {

// Writes studio_cut.png through `out`; returns the report's "studio" section.
nlohmann::json demoStudio(const Mesh& mesh, const Image& exemplar, const std::string& cacheDirectory,
                          const RenderOptions& render, const std::function<std::string(const std::string&)>& out);

// That section as markdown.
std::string studioMarkdown(const nlohmann::json& studio);

}  // namespace texsynth::cli
