#pragma once
// What the studio needs of a mesh before it takes it: triangles, an extent (not every vertex at one
// point) and some area (not every triangle flat). The loaders accept such files (they are well
// formed), but there is nothing to texture or to sketch on, and the field's grid has no size.
#include <string>

#include "texsynth/core/mesh.h"

namespace texsynth::studio {

// Throws InputError(name, problem) for a mesh the studio cannot texture.
void requireTexturableMesh(const Mesh& mesh, const std::string& name);

}  // namespace texsynth::studio
