#pragma once
// What the studio offers to texture: the CGAL meshes and GIMP patterns the project installs, and
// the user's uploads. Every entry has an id the server made up; requests name entries by id only,
// so no path from a request ever reaches the file system. Uploads are size-limited, stored under
// generated names in a private scratch folder (mode 0700, removed with the catalog) and accepted
// only once the project's own loaders (readMesh, readImage) read them without error. A long session's
// uploads do not pile up: the catalog keeps the most recently used few of each kind (besides those the
// scene uses) and forgets the others, their files and, through a listener, what was built from them.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "texsynth/core/temporary_files.h"

namespace texsynth::studio {

struct UploadFile;  // studio_catalog.cpp

struct CatalogEntry {
  std::string id;     // "mesh-3", "exemplar-12", "upload-mesh-1", ...
  std::string name;   // shown to the user: "bunny00", "Stone/pink_marble"
  std::string group;  // "CGAL", a GIMP category, or "uploads"
  std::string path;   // on this machine; never sent to the page
  // An upload's file: removed once the catalog has forgotten the upload and the last copy of its
  // entry is gone (a job still reading it keeps it). Null for installed and command-line files.
  std::shared_ptr<const UploadFile> file;
};

struct UploadLimits {
  std::size_t meshBytes = 64u << 20;
  std::size_t exemplarBytes = 16u << 20;
  int exemplarSide = 2048;           // an uploaded exemplar's longest side, in pixels
  std::size_t jsonBytes = 4u << 20;  // a JSON request body (a curve, a sketch, settings)
  int keptUploads = 8;               // uploads of each kind kept, most recently used first
};

// The uploads kept now, and their files' bytes.
struct UploadUsage {
  int count = 0;
  std::size_t bytes = 0;
};

class StudioCatalog {
 public:
  // Told the id of every upload the catalog forgets (called without the catalog's lock).
  using Forgotten = std::function<void(const std::string& id)>;

  // Lists the installed meshes and patterns (either folder may be missing).
  explicit StudioCatalog(const UploadLimits& limits = {}, Forgotten forgotten = nullptr);

  std::vector<CatalogEntry> meshes() const;
  std::vector<CatalogEntry> exemplars() const;
  // HttpError 404 for an unknown (or forgotten) id. Counts as a use of an upload.
  CatalogEntry mesh(const std::string& id) const;
  CatalogEntry exemplar(const std::string& id) const;
  // The entries the scene uses now: never forgotten, and not counted among the kept uploads.
  void keepInUse(std::set<std::string> ids);
  UploadUsage uploadUsage() const;
  // The first entry whose name is `name` (for the command line's MESH and EXEMPLAR), if any.
  std::optional<CatalogEntry> findByName(const std::string& name, bool mesh) const;
  // Adds a local file given on the command line (validated like an upload, never copied).
  CatalogEntry addLocal(const std::string& path, bool mesh);

  // `format` is the file type (obj ply off stl glb / png jpg jpeg exr pat). HttpError 413 for too
  // many bytes; 400 for an unknown format, a file the loaders reject (their message, naming the
  // upload by `name`) or a mesh with nothing to texture (texturable_mesh.h). Forgets the least
  // recently used uploads of the kind beyond limits.keptUploads.
  CatalogEntry uploadMesh(std::string_view bytes, const std::string& format, const std::string& name);
  CatalogEntry uploadExemplar(std::string_view bytes, const std::string& format, const std::string& name);

 private:
  CatalogEntry upload(std::string_view bytes, const std::string& format, const std::string& name, bool mesh);
  // Finds `id` and stamps it as used; call with the lock held.
  const CatalogEntry& use(const std::vector<CatalogEntry>& entries, const std::string& id, const char* kind) const;
  // Removes the least recently used uploads of `entries` beyond the limit; returns their ids.
  std::vector<std::string> forgetBeyondLimit(std::vector<CatalogEntry>& entries);

  const UploadLimits limits_;
  const Forgotten forgotten_;
  mutable std::mutex mutex_;
  std::vector<CatalogEntry> meshes_, exemplars_;
  std::shared_ptr<ScratchDirectory> uploads_;  // made on the first upload; kept by its files
  int uploadCount_ = 0;
  mutable std::map<std::string, std::uint64_t> lastUse_;  // by upload id
  mutable std::uint64_t clock_ = 0;
  std::set<std::string> inUse_;
};

}  // namespace texsynth::studio
