// The studio's meshes and exemplars: installed data and validated uploads, named by generated ids.
#include "texsynth/studio/studio_catalog.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "texsynth/core/data_paths.h"
#include "texsynth/core/error.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/studio/http_error.h"

namespace texsynth::studio {

namespace fs = std::filesystem;

namespace {

const std::set<std::string> kMeshFormats = {"obj", "ply", "off", "stl", "glb"};
const std::set<std::string> kExemplarFormats = {"png", "jpg", "jpeg", "exr", "pat"};

// Files under `folder` with one of `extensions`, sorted by their path relative to it.
std::vector<fs::path> listFiles(const std::string& folder, const std::set<std::string>& extensions) {
  std::vector<fs::path> files;
  std::error_code error;
  if (!fs::is_directory(folder, error)) return files;
  for (auto it = fs::recursive_directory_iterator(folder, error); !error && it != fs::recursive_directory_iterator();
       it.increment(error)) {
    const std::string ext = it->path().extension().string();
    if (it->is_regular_file(error) && ext.size() > 1 && extensions.count(ext.substr(1))) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The user-facing part of an upload's name: letters, digits, '-', '_' and '.', at most 64.
std::string displayName(const std::string& name, const std::string& fallback) {
  std::string out;
  for (char c : name)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') out += c;
  if (out.size() > 64) out.resize(64);
  return out.empty() ? fallback : out;
}

void validateFile(const std::string& path, bool mesh, int maxSide) {
  if (mesh) {
    readMesh(path);
    return;
  }
  const Image image = readImage(path);
  if (std::max(image.width, image.height) > maxSide)
    throw HttpError(413, "the exemplar is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " pixels; at most " + std::to_string(maxSide) + " on a side");
}

}  // namespace

StudioCatalog::StudioCatalog(const UploadLimits& limits) : limits_(limits) {
  int n = 0;
  for (const fs::path& file : listFiles(cgalMeshDirectory(), {"off"}))
    meshes_.push_back({"mesh-" + std::to_string(++n), file.stem().string(), "CGAL", file.string()});
  n = 0;
  const std::string patterns = gimpPatternDirectory();
  for (const fs::path& file : listFiles(patterns, {"pat"})) {
    const std::string category = file.parent_path().filename().string();
    exemplars_.push_back(
        {"exemplar-" + std::to_string(++n), category + "/" + file.stem().string(), category, file.string()});
  }
}

std::vector<CatalogEntry> StudioCatalog::meshes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return meshes_;
}

std::vector<CatalogEntry> StudioCatalog::exemplars() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return exemplars_;
}

CatalogEntry StudioCatalog::mesh(const std::string& id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const CatalogEntry& entry : meshes_)
    if (entry.id == id) return entry;
  throw notFound("mesh '" + id + "'");
}

CatalogEntry StudioCatalog::exemplar(const std::string& id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const CatalogEntry& entry : exemplars_)
    if (entry.id == id) return entry;
  throw notFound("exemplar '" + id + "'");
}

std::optional<CatalogEntry> StudioCatalog::findByName(const std::string& name, bool mesh) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto& entries = mesh ? meshes_ : exemplars_;
  for (const CatalogEntry& entry : entries)
    if (entry.name == name || fs::path(entry.name).filename() == name) return entry;
  return std::nullopt;
}

CatalogEntry StudioCatalog::addLocal(const std::string& path, bool mesh) {
  validateFile(path, mesh, mesh ? 0 : 1 << 16);
  std::lock_guard<std::mutex> lock(mutex_);
  auto& entries = mesh ? meshes_ : exemplars_;
  CatalogEntry entry{(mesh ? "local-mesh-" : "local-exemplar-") + std::to_string(entries.size() + 1),
                     fs::path(path).stem().string(), "command line", path};
  entries.push_back(entry);
  return entry;
}

CatalogEntry StudioCatalog::uploadMesh(std::string_view bytes, const std::string& format, const std::string& name) {
  return upload(bytes, format, name, true);
}

CatalogEntry StudioCatalog::uploadExemplar(std::string_view bytes, const std::string& format, const std::string& name) {
  return upload(bytes, format, name, false);
}

CatalogEntry StudioCatalog::upload(std::string_view bytes, const std::string& format, const std::string& name,
                                   bool mesh) {
  std::string ext = format;
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const auto& formats = mesh ? kMeshFormats : kExemplarFormats;
  if (!formats.count(ext)) {
    std::string list;
    for (const std::string& f : formats) list += (list.empty() ? "" : " ") + f;
    throw HttpError(400, "format '" + format + "': give one of " + list);
  }
  const std::size_t limit = mesh ? limits_.meshBytes : limits_.exemplarBytes;
  if (bytes.size() > limit)
    throw HttpError(413, std::string(mesh ? "mesh" : "exemplar") + " upload of " + std::to_string(bytes.size()) +
                             " bytes; at most " + std::to_string(limit));
  if (bytes.empty()) throw HttpError(400, "the upload is empty");
  std::string path;
  int number;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!uploads_) uploads_ = std::make_unique<ScratchDirectory>("studio uploads");
    number = ++uploadCount_;
    path = (fs::path(uploads_->path()) / ("upload-" + std::to_string(number) + "." + ext)).string();
  }
  {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) throw OutputError("studio uploads", "cannot store the upload");
  }
  const std::string shown = displayName(name, "upload-" + std::to_string(number));
  try {
    validateFile(path, mesh, limits_.exemplarSide);
  } catch (const Error& e) {
    std::error_code ignored;
    fs::remove(path, ignored);
    // The loaders name the file by its generated path: the user knows it by the upload's name.
    std::string message = e.what();
    for (std::size_t at; (at = message.find(path)) != std::string::npos;) message.replace(at, path.size(), shown);
    throw HttpError(400, message);
  } catch (...) {
    std::error_code ignored;
    fs::remove(path, ignored);
    throw;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  CatalogEntry entry{std::string(mesh ? "upload-mesh-" : "upload-exemplar-") + std::to_string(number), shown, "uploads",
                     path};
  (mesh ? meshes_ : exemplars_).push_back(entry);
  return entry;
}

}  // namespace texsynth::studio
