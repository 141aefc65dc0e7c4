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
#include "texsynth/studio/texturable_mesh.h"

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
    requireTexturableMesh(readMesh(path), path);
    return;
  }
  const Image image = readImage(path);
  if (std::max(image.width, image.height) > maxSide)
    throw HttpError(413, "the exemplar is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " pixels; at most " + std::to_string(maxSide) + " on a side");
}

}  // namespace

// An upload's file in the scratch folder, which it keeps while it exists.
struct UploadFile {
  std::shared_ptr<ScratchDirectory> folder;
  std::string path;
  std::size_t bytes = 0;
  ~UploadFile() {
    std::error_code ignored;
    fs::remove(path, ignored);
  }
};

StudioCatalog::StudioCatalog(const UploadLimits& limits, Forgotten forgotten)
    : limits_(limits), forgotten_(std::move(forgotten)) {
  int n = 0;
  for (const fs::path& file : listFiles(cgalMeshDirectory(), {"off"}))
    meshes_.push_back({"mesh-" + std::to_string(++n), file.stem().string(), "CGAL", file.string(), nullptr});
  n = 0;
  const std::string patterns = gimpPatternDirectory();
  for (const fs::path& file : listFiles(patterns, {"pat"})) {
    const std::string category = file.parent_path().filename().string();
    exemplars_.push_back(
        {"exemplar-" + std::to_string(++n), category + "/" + file.stem().string(), category, file.string(), nullptr});
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

const CatalogEntry& StudioCatalog::use(const std::vector<CatalogEntry>& entries, const std::string& id,
                                       const char* kind) const {
  for (const CatalogEntry& entry : entries)
    if (entry.id == id) {
      if (entry.file) lastUse_[id] = ++clock_;
      return entry;
    }
  throw notFound(std::string(kind) + " '" + id + "'");
}

CatalogEntry StudioCatalog::mesh(const std::string& id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return use(meshes_, id, "mesh");
}

CatalogEntry StudioCatalog::exemplar(const std::string& id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return use(exemplars_, id, "exemplar");
}

void StudioCatalog::keepInUse(std::set<std::string> ids) {
  std::lock_guard<std::mutex> lock(mutex_);
  inUse_ = std::move(ids);
}

UploadUsage StudioCatalog::uploadUsage() const {
  std::lock_guard<std::mutex> lock(mutex_);
  UploadUsage usage;
  for (const auto* entries : {&meshes_, &exemplars_})
    for (const CatalogEntry& entry : *entries)
      if (entry.file) ++usage.count, usage.bytes += entry.file->bytes;
  return usage;
}

std::vector<std::string> StudioCatalog::forgetBeyondLimit(std::vector<CatalogEntry>& entries) {
  std::vector<std::pair<std::uint64_t, std::string>> uploads;  // (last use, id), not in use
  for (const CatalogEntry& entry : entries)
    if (entry.file && !inUse_.count(entry.id)) uploads.push_back({lastUse_[entry.id], entry.id});
  std::vector<std::string> forgotten;
  if (uploads.size() <= std::size_t(limits_.keptUploads)) return forgotten;
  std::sort(uploads.begin(), uploads.end());
  for (std::size_t i = 0; i + std::size_t(limits_.keptUploads) < uploads.size(); ++i)
    forgotten.push_back(uploads[i].second);
  std::erase_if(entries, [&](const CatalogEntry& entry) {
    return std::find(forgotten.begin(), forgotten.end(), entry.id) != forgotten.end();
  });
  for (const std::string& id : forgotten) lastUse_.erase(id);
  return forgotten;
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
                     fs::path(path).stem().string(), "command line", path, nullptr};
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
  std::shared_ptr<UploadFile> file = std::make_shared<UploadFile>();
  int number;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!uploads_) uploads_ = std::make_shared<ScratchDirectory>("studio uploads");
    number = ++uploadCount_;
    file->folder = uploads_;
    file->path = (fs::path(uploads_->path()) / ("upload-" + std::to_string(number) + "." + ext)).string();
    file->bytes = bytes.size();
  }
  const std::string& path = file->path;
  {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) throw OutputError("studio uploads", "cannot store the upload");
  }
  const std::string shown = displayName(name, "upload-" + std::to_string(number));
  try {
    validateFile(path, mesh, limits_.exemplarSide);
  } catch (const Error& e) {
    // The loaders name the file by its generated path: the user knows it by the upload's name.
    std::string message = e.what();
    for (std::size_t at; (at = message.find(path)) != std::string::npos;) message.replace(at, path.size(), shown);
    throw HttpError(400, message);
  }
  CatalogEntry entry{std::string(mesh ? "upload-mesh-" : "upload-exemplar-") + std::to_string(number), shown, "uploads",
                     path, std::move(file)};
  std::vector<std::string> forgotten;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& entries = mesh ? meshes_ : exemplars_;
    entries.push_back(entry);
    lastUse_[entry.id] = ++clock_;
    forgotten = forgetBeyondLimit(entries);
  }
  if (forgotten_)
    for (const std::string& id : forgotten) forgotten_(id);
  return entry;
}

}  // namespace texsynth::studio
