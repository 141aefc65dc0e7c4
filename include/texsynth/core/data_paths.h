#pragma once
// Where real data lives: GIMP patterns (gimp-data), CGAL demo meshes (extracted from
// libcgal-demo by scripts/install-deps.sh) and assimp's malformed models.
#include <optional>
#include <string>

namespace texsynth {

// Directory of extracted data; $TEXSYNTH_DATA overrides the build-time default.
std::string dataDirectory();
// Where GIMP's patterns (one folder per category) and the extracted CGAL meshes live; the folders
// may be missing.
std::string gimpPatternDirectory();
std::string cgalMeshDirectory();
// A GIMP pattern by relative name, e.g. "Stone/marble1.pat", if installed.
std::optional<std::string> gimpPattern(const std::string& relative);
// A CGAL demo mesh by file name, e.g. "bunny00.off", if extracted.
std::optional<std::string> cgalMesh(const std::string& name);
// Directory of assimp's malformed test models, if installed.
std::optional<std::string> assimpInvalidModels();

}  // namespace texsynth
