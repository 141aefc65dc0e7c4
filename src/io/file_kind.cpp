#include "texsynth/io/file_kind.h"

#include <algorithm>
#include <array>
#include <string_view>

#include "texsynth/core/atomic_file.h"

namespace texsynth {

static constexpr std::array<std::string_view, 7> kImage = {"png", "jpg", "jpeg", "bmp", "tga", "exr", "pat"};
static constexpr std::array<std::string_view, 6> kMesh = {"obj", "ply", "off", "stl", "glb", "gltf"};
static constexpr std::array<std::string_view, 2> kVolume = {"nrrd", "vdb"};
static constexpr std::array<std::string_view, 1> kField = {"tsfield"};
static constexpr std::array<std::string_view, 1> kGradientSolid = {"tsgs"};

template <std::size_t N>
static bool contains(const std::array<std::string_view, N>& list, const std::string& ext) {
  return std::find(list.begin(), list.end(), ext) != list.end();
}

template <std::size_t N>
static std::string join(const std::array<std::string_view, N>& list) {
  std::string text;
  for (auto ext : list) text += (text.empty() ? "." : " .") + std::string(ext);
  return text;
}

FileKind fileKind(const std::string& path) {
  std::string ext = fileExtension(path);
  if (contains(kImage, ext)) return FileKind::Image;
  if (contains(kMesh, ext)) return FileKind::Mesh;
  if (contains(kVolume, ext)) return FileKind::Volume;
  if (contains(kField, ext)) return FileKind::Field;
  if (contains(kGradientSolid, ext)) return FileKind::GradientSolid;
  return FileKind::Unknown;
}

std::string readableImageExtensions() {
  return join(kImage);
}
std::string readableMeshExtensions() {
  return join(kMesh);
}
std::string readableVolumeExtensions() {
  return join(kVolume);
}
std::string readableFieldExtensions() {
  return join(kField);
}
std::string readableGradientSolidExtensions() {
  return join(kGradientSolid);
}

}  // namespace texsynth
