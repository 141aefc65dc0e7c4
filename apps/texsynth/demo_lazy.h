#pragma once
// The demo's lazy solid section: a rotation field designed from one sketch curve laid over the
// mesh, the lazy solid following it rendered (first picture), then the mesh cut open (a new cut
// synthesizes only the voxels it exposes), timed per level.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"
#include "texsynth/field/sketch.h"
#include "texsynth/render/render_mesh.h"

namespace texsynth::cli {

// One curve over the top of the mesh along its longest horizontal side, snapped to the surface:
// the exemplar's x follows it, its y the surface normal. Works on any mesh (no curve if the mesh
// is too small to hold one).
Sketch sketchOverTheTop(const Mesh& mesh);

// Writes lazy_solid.png (the views, then the cut) through `out`; returns the report's
// "lazy_solid" section.
nlohmann::json demoLazySolid(const Mesh& mesh, const Image& exemplar, const std::string& exemplarName,
                             std::uint64_t seed, const std::string& cacheDirectory, const RenderOptions& render,
                             const std::vector<std::pair<float, float>>& views,
                             const std::function<std::string(const std::string&)>& out);

// That section as markdown.
std::string lazySolidMarkdown(const nlohmann::json& lazy);

}  // namespace texsynth::cli
