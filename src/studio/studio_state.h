#pragma once
// What the studio server's routes share (private to the studio module).
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "studio_router.h"
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
  // Tells the catalog which uploads the scene uses (never forgotten). Call with `mutex` held, after
  // every change of the scene's mesh or exemplar.
  void keepSceneInUse();
};

// Routes: the catalog, uploads, the scene, sketch and field (studio_scene_routes.cpp) and the
// synthesis jobs, results and exports (studio_synthesis_routes.cpp).
void addSceneRoutes(StudioRouter& router, StudioState& state);
void addSynthesisRoutes(StudioRouter& router, StudioState& state);

// Runs `handle`, answering its exceptions as JSON {"error": message} with 400 for the library's
// input and parameter errors (and nlohmann's, for a JSON value of the wrong type), the HttpError's
// own status, and 500 for anything else; no message names a temporary file (public_message.h).
void answer(httplib::Response& response, const std::function<void()>& handle);
// The request body as JSON (an empty body is {}); InputError "request body: not valid JSON at line
// L, column C: ..." otherwise.
nlohmann::json jsonBody(const httplib::Request& request);
void sendJson(httplib::Response& response, const nlohmann::json& body, int status = 200);

}  // namespace texsynth::studio
