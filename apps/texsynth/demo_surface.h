#pragma once
// The demo's surface section: a texture grown on the demo mesh by discrete optimization
// (`texsynth surface`), timed per stage and scored with the surface coherence measure.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"

namespace texsynth::cli {

// Writes surface_synthesis.png (two views of `exemplar` grown on `mesh`, retiled to a demo-sized
// vertex count) through `out` and returns the report's "surface" section. The mesh hierarchy and
// the exemplar analyses go through the caches in `cacheDirectory`.
nlohmann::json demoSurfaceSynthesis(const Mesh& mesh, const std::string& meshName, const Image& exemplar,
                                    const std::string& exemplarName, std::uint64_t seed,
                                    const std::string& cacheDirectory,
                                    const std::function<std::string(const std::string&)>& out);

// That section as markdown.
std::string surfaceMarkdown(const nlohmann::json& surface);

}  // namespace texsynth::cli
