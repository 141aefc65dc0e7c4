#pragma once
// `texsynth studio`: a local web app for the sketch-guided solid texturing workflow. The server
// (cpp-httplib) serves the page from the project's web/ folder (three.js from its npm install,
// no CDN) and a JSON API (docs/studio-api.md) that the page and the tests use: the catalog and
// uploads, the sketch curves and the field's glyphs, previews and cuts synthesized by workers
// (newer requests supersede stale ones), exports, and a Server-Sent Events stream of job states,
// progress and results.
#include <memory>
#include <string>

#include "texsynth/studio/studio_catalog.h"

namespace texsynth::studio {

class EventHub;
class JobLanes;

struct StudioOptions {
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port (tests)
  // Folder with index.html, app.js, style.css and node_modules/three (InputError at construction if
  // it holds no index.html); empty: the API only.
  std::string webRoot;
  int workers = 2;  // synthesis threads (each job also uses the library's parallel loops)
  UploadLimits limits;
  std::string cacheDirectory;  // disk cache shared with the command line (exemplar analysis, lazy levels)
  // The models are subdivided to at least this many vertices (at most 4x) for per-vertex colours.
  std::size_t displayVertices = 100000;
  // Chosen at start: a catalog name ("bunny00", "Stone/pink_marble") or a file path; may be empty.
  std::string mesh, exemplar;
};

class StudioServer {
 public:
  // Loads the catalog, the page's file list and the initial mesh and exemplar; throws their errors.
  explicit StudioServer(StudioOptions options);
  ~StudioServer();
  StudioServer(const StudioServer&) = delete;
  StudioServer& operator=(const StudioServer&) = delete;

  // Binds and serves on background threads; returns the port. Throws OutputError when the
  // address cannot be bound.
  int start();
  void stop();

  EventHub& events();
  JobLanes& jobs();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace texsynth::studio
