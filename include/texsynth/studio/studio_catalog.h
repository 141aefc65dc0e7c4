#pragma once
// What the studio offers to texture: the CGAL meshes and GIMP patterns the project installs, and
// the user's uploads. Every entry has an id the server made up; requests name entries by id only,
// so no path from a request ever reaches the file system. Uploads are size-limited, stored under
// generated names in a private scratch folder (mode 0700, removed with the catalog) and accepted
// only once the project's own loaders (readMesh, readImage) read them without error.
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "texsynth/core/temporary_files.h"

namespace texsynth::studio {

struct CatalogEntry {
  std::string id;     // "mesh-3", "exemplar-12", "upload-mesh-1", ...
  std::string name;   // shown to the user: "bunny00", "Stone/pink_marble"
  std::string group;  // "CGAL", a GIMP category, or "uploads"
  std::string path;   // on this machine; never sent to the page
};

struct UploadLimits {
  std::size_t meshBytes = 64u << 20;
  std::size_t exemplarBytes = 16u << 20;
  int exemplarSide = 2048;  // an uploaded exemplar's longest side, in pixels
};

class StudioCatalog {
 public:
  // Lists the installed meshes and patterns (either folder may be missing).
  explicit StudioCatalog(const UploadLimits& limits = {});

  std::vector<CatalogEntry> meshes() const;
  std::vector<CatalogEntry> exemplars() const;
  // HttpError 404 for an unknown id.
  CatalogEntry mesh(const std::string& id) const;
  CatalogEntry exemplar(const std::string& id) const;
  // The first entry whose name is `name` (for the command line's MESH and EXEMPLAR), if any.
  std::optional<CatalogEntry> findByName(const std::string& name, bool mesh) const;
  // Adds a local file given on the command line (validated like an upload, never copied).
  CatalogEntry addLocal(const std::string& path, bool mesh);

  // `format` is the file type (obj ply off stl glb / png jpg jpeg exr pat). HttpError 413 for too
  // many bytes; 400 for an unknown format or a file the loaders reject (their message).
  CatalogEntry uploadMesh(std::string_view bytes, const std::string& format, const std::string& name);
  CatalogEntry uploadExemplar(std::string_view bytes, const std::string& format, const std::string& name);

 private:
  CatalogEntry upload(std::string_view bytes, const std::string& format, const std::string& name, bool mesh);
  const UploadLimits limits_;
  mutable std::mutex mutex_;
  std::vector<CatalogEntry> meshes_, exemplars_;
  std::unique_ptr<ScratchDirectory> uploads_;  // made on the first upload
  int uploadCount_ = 0;
};

}  // namespace texsynth::studio
