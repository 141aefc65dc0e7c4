// The studio's HTTP plumbing: the page's static files from an allow-list, the event stream,
// error answers, and the server's life cycle. Routing by path and method is studio_router.cpp's.
#include "texsynth/studio/studio_server.h"

#include <sys/socket.h>

#include <filesystem>
#include <thread>

#include "studio_state.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/io/json_input.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/studio/public_message.h"

namespace texsynth::studio {

namespace fs = std::filesystem;

namespace {

const std::map<std::string, std::string> kContentTypes = {{".html", "text/html; charset=utf-8"},
                                                          {".js", "text/javascript; charset=utf-8"},
                                                          {".css", "text/css; charset=utf-8"},
                                                          {".svg", "image/svg+xml"},
                                                          {".png", "image/png"}};

// Every file the page may load, by URL path, found once at start: the web folder's own files and
// the npm packages' modules. A request's path is only ever looked up here, never joined to a folder.
// InputError for a folder given that does not hold the page.
std::map<std::string, fs::path> webAssets(const std::string& webRoot) {
  std::map<std::string, fs::path> assets;
  if (webRoot.empty()) return assets;
  std::error_code error;
  if (!fs::is_directory(webRoot, error))
    throw InputError(webRoot, "no such folder; give the folder with the studio's page (index.html), e.g. web/");
  if (!fs::is_regular_file(fs::path(webRoot) / "index.html", error))
    throw InputError(webRoot, "holds no index.html: not the folder with the studio's page (e.g. web/)");
  for (const auto& entry : fs::directory_iterator(webRoot, error))
    if (entry.is_regular_file() && kContentTypes.count(entry.path().extension().string()))
      assets[std::string("/").append(entry.path().filename().string())] = entry.path();  // (gcc 12: not "/" + s)
  // The npm packages' module builds the page imports (web/package.json), served under /vendor/.
  const std::pair<const char*, const char*> kVendorFolders[] = {
      {"three", "build"}, {"three", "examples/jsm"}, {"three-mesh-bvh", "build"}};
  for (const auto& [package, folder] : kVendorFolders) {
    const fs::path root = fs::path(webRoot) / "node_modules" / package;
    if (!fs::is_directory(root / folder, error)) continue;
    for (auto it = fs::recursive_directory_iterator(root / folder, error);
         !error && it != fs::recursive_directory_iterator(); it.increment(error))
      if (it->is_regular_file() && it->path().extension() == ".js")
        assets[std::string("/vendor/") + package + "/" + fs::relative(it->path(), root).generic_string()] = it->path();
  }
  if (assets.count("/index.html")) assets["/"] = assets["/index.html"];
  return assets;
}

// httplib's server with room for bursts of new connections: the library listens with a backlog of
// 5, and when more arrive at once (fifty clients of a load test, a page opening its connections)
// some were reset after a second. Linux takes a second listen() on the bound socket as the new size.
class HttpServer : public httplib::Server {
 public:
  void widenBacklog() { ::listen(svr_sock_, SOMAXCONN); }
};

// nlohmann's "[json.exception.type_error.302] type must be number, but is null" -> "type must be ...".
std::string withoutLibraryTag(std::string message) {
  if (message.rfind("[json.exception.", 0) == 0) message.erase(0, message.find("] ") + 2);
  return message;
}

}  // namespace

StudioState::StudioState(const StudioOptions& options)
    : options(options),
      catalog(options.limits, [this](const std::string& id) { solids.forgetExemplar(id); }),
      jobs(std::make_unique<JobLanes>(options.workers, events)) {}

std::shared_ptr<StudioScene> StudioState::requireScene() const {
  if (!scene) throw HttpError(409, "no mesh chosen yet: POST /api/scene {\"mesh\": ID} first");
  return scene;
}

void StudioState::keepSceneInUse() {
  catalog.keepInUse({scene ? scene->meshId() : "", texture.exemplarId});
}

void sendJson(httplib::Response& response, const nlohmann::json& body, int status) {
  response.status = status;
  response.set_content(body.dump(), "application/json");
}

void answer(httplib::Response& response, const std::function<void()>& handle) {
  const auto fail = [&response](const std::string& message, int status) {
    sendJson(response, {{"error", withoutTemporaryPaths(message)}}, status);
  };
  try {
    handle();
  } catch (const HttpError& e) {
    fail(e.what(), e.status());
  } catch (const InputError& e) {
    fail(e.what(), 400);
  } catch (const ParameterError& e) {
    fail(e.what(), 400);
  } catch (const nlohmann::json::exception& e) {  // a value of a type the route did not check
    fail("request body: " + withoutLibraryTag(e.what()), 400);
  } catch (const std::exception& e) {
    fail(std::string("internal error: ") + e.what(), 500);
  }
}

nlohmann::json jsonBody(const httplib::Request& request) {
  if (request.body.empty()) return nlohmann::json::object();
  return json_input::parse(request.body, "request body");
}

struct StudioServer::Impl {
  explicit Impl(StudioOptions options) : state(options), assets(webAssets(options.webRoot)) {}
  StudioState state;
  std::map<std::string, fs::path> assets;
  StudioRouter router;
  HttpServer http;
  std::thread listener;
  int port = 0;
};

StudioServer::StudioServer(StudioOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  StudioState& state = impl_->state;
  httplib::Server& http = impl_->http;
  StudioRouter& router = impl_->router;
  // Room for the event streams of many pages and a load test's clients at once.
  http.new_task_queue = [] { return new httplib::ThreadPool(64); };
  // Pages and clients keep their connection (a browser opens a few per host): far fewer new
  // connections through the listen backlog, which drops some when many arrive at once.
  http.set_keep_alive_max_count(1000);
  // On a kept connection a response's header and body go out as two writes: without TCP_NODELAY the
  // second waits for the client's delayed ACK, 40 ms a request.
  http.set_tcp_nodelay(true);
  // Address reuse only: httplib's default also sets SO_REUSEPORT, under which a second studio on
  // the same port would bind too and share the requests instead of failing.
  http.set_socket_options([](socket_t socket) {
    const int yes = 1;
    setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  // The largest body any route takes; each route reads its own up to its own limit (studio_router.h).
  const UploadLimits& limits = state.options.limits;
  http.set_payload_max_length(std::max({limits.meshBytes, limits.exemplarBytes, limits.jsonBytes}));
  http.set_exception_handler([](const httplib::Request&, httplib::Response& response, std::exception_ptr) {
    sendJson(response, {{"error", "internal error"}}, 500);
  });
  http.set_error_handler([](const httplib::Request& request, httplib::Response& response) {
    if (!response.body.empty()) return;
    const std::string what = response.status == 404   ? "no such route: " + request.method + " " + request.path
                             : response.status == 413 ? "the request body is too large"
                                                      : "bad request";
    sendJson(response, {{"error", what}}, response.status);
  });

  router.get("/api/health", [&state](const httplib::Request&, httplib::Response& response) {
    const UploadUsage uploads = state.catalog.uploadUsage();
    std::lock_guard<std::mutex> lock(state.mutex);
    sendJson(response, {{"status", "ok"},
                        {"version", "texsynth studio 1"},
                        {"mesh", state.scene ? state.scene->meshId() : ""},
                        {"exemplar", state.texture.exemplarId},
                        {"results_mib", double(state.results.bytes()) / (1 << 20)},
                        {"uploads", uploads.count},
                        {"uploads_mib", double(uploads.bytes) / (1 << 20)}});
  });
  router.get("/api/events", [&state](const httplib::Request& request, httplib::Response& response) {
    std::int64_t after = state.events.lastId();  // a new page starts from now
    if (request.has_header("Last-Event-ID")) {
      try {
        after = std::stoll(request.get_header_value("Last-Event-ID"));
      } catch (const std::exception&) {
        sendJson(response, {{"error", "Last-Event-ID: give the id of the last event seen"}}, 400);
        return;
      }
    }
    response.set_header("Cache-Control", "no-cache");
    response.set_chunked_content_provider("text/event-stream", [&state, after](std::size_t, httplib::DataSink& sink) {
      std::int64_t last = after;
      const std::string hello = ": texsynth studio events\n\n";
      if (!sink.write(hello.data(), hello.size())) return false;
      while (!state.events.closed() && sink.is_writable()) {
        const auto events = state.events.waitAfter(last, std::chrono::seconds(10));
        std::string text = events.empty() ? ": keep-alive\n\n" : "";
        for (const StudioEvent& event : events) text += formatServerSentEvent(event), last = event.id;
        if (!sink.write(text.data(), text.size())) return false;
      }
      sink.done();
      return true;
    });
  });
  addSceneRoutes(router, state);
  addSynthesisRoutes(router, state);
  // The page's files: any path outside /api/; a file that is not there is 404 for every method.
  const auto servePage = [this](const httplib::Request& request, httplib::Response& response) {
    const auto it = impl_->assets.find(request.path);
    if (it == impl_->assets.end()) {
      const bool noPage = impl_->assets.find("/") == impl_->assets.end();
      sendJson(response,
               {{"error", noPage && request.path == "/"
                              ? "the page is not installed: run scripts/install-deps.sh (web/node_modules)"
                              : "no such file: " + request.path}},
               404);
      return;
    }
    response.set_header("Cache-Control", "no-cache");
    response.set_content(readFileBytes(it->second.string()), kContentTypes.at(it->second.extension().string()));
  };
  router.get(R"(/(?!api/).*)", servePage, [this](const std::string& path) { return impl_->assets.count(path) > 0; });
  router.install(http);

  // The mesh and exemplar to start with, by catalog name or as a local file.
  std::lock_guard<std::mutex> lock(state.mutex);
  // A name the catalog does not know must be a file.
  const auto local = [&state](const std::string& name, bool mesh) {
    std::error_code error;
    if (!fs::exists(name, error))
      throw InputError(name, std::string("neither a ") + (mesh ? "mesh" : "pattern") +
                                 " of the catalog (GET /api/catalog, e.g. " + (mesh ? "bunny00" : "Stone/pink_marble") +
                                 ") nor a file");
    return state.catalog.addLocal(name, mesh);
  };
  if (!state.options.exemplar.empty()) {
    const auto found = state.catalog.findByName(state.options.exemplar, false);
    state.texture.exemplarId = found ? found->id : local(state.options.exemplar, false).id;
  } else if (!state.catalog.exemplars().empty()) {
    state.texture.exemplarId = state.catalog.exemplars().front().id;
  }
  if (!state.options.mesh.empty()) {
    const auto found = state.catalog.findByName(state.options.mesh, true);
    const CatalogEntry entry = found ? *found : local(state.options.mesh, true);
    state.scene =
        std::make_shared<StudioScene>(entry.id, entry.name, readMesh(entry.path), state.options.displayVertices);
    ++state.sceneSerial;
  }
  state.keepSceneInUse();
}

StudioServer::~StudioServer() {
  stop();
}

int StudioServer::start() {
  const StudioOptions& options = impl_->state.options;
  impl_->port = options.port == 0 ? impl_->http.bind_to_any_port(options.host)
                                  : (impl_->http.bind_to_port(options.host, options.port) ? options.port : -1);
  if (impl_->port <= 0)
    throw OutputError(options.host + ":" + std::to_string(options.port),
                      "cannot listen there (in use, or not an address of this machine)");
  impl_->http.widenBacklog();
  impl_->listener = std::thread([this] { impl_->http.listen_after_bind(); });
  return impl_->port;
}

void StudioServer::stop() {
  impl_->state.events.close();  // event streams end, so their threads return
  impl_->http.stop();
  if (impl_->listener.joinable()) impl_->listener.join();
}

EventHub& StudioServer::events() {
  return impl_->state.events;
}
JobLanes& StudioServer::jobs() {
  return *impl_->state.jobs;
}

}  // namespace texsynth::studio
