#include "texsynth/core/data_paths.h"

#include <cstdlib>
#include <filesystem>

namespace texsynth {
namespace fs = std::filesystem;

#ifndef TEXSYNTH_DATA_DIR
#define TEXSYNTH_DATA_DIR ".data"
#endif

static std::optional<std::string> existing(const fs::path& p) {
  std::error_code ec;
  if (fs::exists(p, ec)) return p.string();
  return std::nullopt;
}

std::string dataDirectory() {
  if (const char* env = std::getenv("TEXSYNTH_DATA"); env && *env) return env;
  return TEXSYNTH_DATA_DIR;
}

std::string gimpPatternDirectory() {
  return "/usr/share/gimp/2.0/patterns";
}

std::string cgalMeshDirectory() {
  return (fs::path(dataDirectory()) / "meshes").string();
}

std::optional<std::string> gimpPattern(const std::string& relative) {
  return existing(fs::path(gimpPatternDirectory()) / relative);
}

std::optional<std::string> cgalMesh(const std::string& name) {
  return existing(fs::path(cgalMeshDirectory()) / name);
}

std::optional<std::string> assimpInvalidModels() {
  return existing("/usr/share/assimp/models/invalid");
}

}  // namespace texsynth
