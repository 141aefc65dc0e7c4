#pragma once
// What the studio server's routes share (private to the studio module).
#include <httplib.h>

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>
// httplib brings <resolv.h>, whose `_res` macro breaks Eigen's products (a parameter of that name).
#undef _res

#include "texsynth/studio/event_hub.h"
#include "texsynth/studio/http_error.h"
#include "texsynth/studio/job_lanes.h"
#include "texsynth/studio/result_store.h"
#include "texsynth/studio/studio_catalog.h"
#include "texsynth/studio/studio_scene.h"
#include "texsynth/studio/studio_server.h"
#include "texsynth/studio/studio_solids.h"

namespace texsynth::studio {

struct StudioState {
  explicit StudioState(const StudioOptions& options);

  StudioOptions options;
  StudioCatalog catalog;
  EventHub events;
  ResultStore results;
  SolidShelf solids;
  std::unique_ptr<JobLanes> jobs;  // declared after what its jobs use, so it is joined first on destruction

  std::mutex mutex;  // guards scene, sceneSerial and texture
  std::shared_ptr<StudioScene> scene;
  int sceneSerial = 0;  // counts mesh changes: solids and results of an older scene are never mixed in
  TextureSettings texture;

  // The scene or HttpError 409 when no mesh is chosen yet. Call with `mutex` held.
  std::shared_ptr<StudioScene> requireScene() const;
};

// Routes: the catalog, uploads, the scene, sketch and field (studio_scene_routes.cpp) and the
// synthesis jobs, results and exports (studio_synthesis_routes.cpp).
void addSceneRoutes(httplib::Server& server, StudioState& state);
void addSynthesisRoutes(httplib::Server& server, StudioState& state);

// Runs `handle`, answering its exceptions as JSON {"error": message} with 400 for the library's
// input and parameter errors, the HttpError's own status, and 500 for anything else.
void answer(httplib::Response& response, const std::function<void()>& handle);
// The request body as JSON: HttpError 400 "malformed JSON ..." otherwise (an empty body is {}).
nlohmann::json jsonBody(const httplib::Request& request);
void sendJson(httplib::Response& response, const nlohmann::json& body, int status = 200);

}  // namespace texsynth::studio
