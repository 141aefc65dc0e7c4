// The demo's studio section: the studio server driven through its HTTP API.
#include "demo_studio.h"

#include <httplib.h>
#undef _res  // from <resolv.h>, via httplib: it breaks Eigen's products

#include <chrono>
#include <sstream>

#include "demo_lazy.h"
#include "demo_pixel.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/temporary_files.h"
#include "texsynth/core/timing.h"
#include "texsynth/field/sketch.h"
#include "texsynth/geometry/mesh_cut.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/view_up.h"
#include "texsynth/studio/event_hub.h"
#include "texsynth/studio/studio_server.h"

namespace texsynth::cli {

using nlohmann::json;

namespace {

// The "result" event of `job`, published in-process by the server's workers.
json waitForResult(studio::StudioServer& server, const std::string& job) {
  const auto event = server.events().waitFor(
      [&](const studio::StudioEvent& e) {
        return (e.type == "result" && e.data["job"] == job && e.data.value("stage", "final") == "final") ||
               (e.type == "job" && e.data["id"] == job && e.data["state"] == "failed");
      },
      std::chrono::minutes(2));
  if (!event || event->type != "result")
    throw InternalError("studio job " + job + " gave no result" + (event ? ": " + event->data.dump() : ""));
  return event->data;
}

json call(httplib::Client& client, const std::string& method, const std::string& path, const json& body = {}) {
  const httplib::Result r = method == "POST"     ? client.Post(path.c_str(), body.dump(), "application/json")
                            : method == "DELETE" ? client.Delete(path.c_str())
                                                 : client.Get(path.c_str());
  if (!r || r->status >= 400)
    throw InternalError("studio " + method + " " + path + ": " + (r ? r->body : std::string("no answer")));
  return r->get_header_value("Content-Type") == "application/json" ? json::parse(r->body) : json{{"bytes", r->body}};
}

}  // namespace

json demoStudio(const Mesh& mesh, const Image& exemplar, const std::string& cacheDirectory, const RenderOptions& render,
                const std::function<std::string(const std::string&)>& out) {
  json section;
  ScratchDirectory scratch("the demo's studio section");
  // Scratch inputs for the server, written at once (the run's outputs wait for its end).
  writeFileAtomically(scratch.path() + "/model.ply", encodePly(mesh), Staging::Immediately);
  writeFileAtomically(scratch.path() + "/exemplar.png", encodePngBytes(exemplar.withChannels(3)), Staging::Immediately);
  studio::StudioOptions options;
  options.port = 0;
  options.cacheDirectory = cacheDirectory;
  options.mesh = scratch.path() + "/model.ply";
  options.exemplar = scratch.path() + "/exemplar.png";
  auto started = std::chrono::steady_clock::now();
  studio::StudioServer server(options);
  httplib::Client client("127.0.0.1", server.start());
  client.set_read_timeout(300, 0);
  section["start_seconds"] = secondsSince(started);
  section["display_vertices"] = call(client, "GET", "/api/scene")["mesh"]["display_vertices"];

  // A curve to the updated field and its glyphs, five times (each undone, so every one is new).
  const Sketch sketch = sketchOverTheTop(mesh);
  if (!sketch.curves.empty()) {
    const json curve = json::parse(encodeSketch(sketch))["curves"][0];
    std::vector<double> ms;
    for (int i = 0; i < 5; ++i) {
      started = std::chrono::steady_clock::now();
      const json added = call(client, "POST", "/api/sketch/curves", curve);
      call(client, "GET", "/api/field/glyphs");
      ms.push_back(1000 * secondsSince(started));
      if (i < 4) call(client, "DELETE", "/api/sketch/curves/" + added["id"].get<std::string>());
    }
    std::sort(ms.begin(), ms.end());
    section["curve_ms"] = {{"median", ms[2]}, {"max", ms[4]}};
  }
  // A textured preview (tile-deform) and a cut through the model with it, as the page asks.
  started = std::chrono::steady_clock::now();
  json preview = waitForResult(server, call(client, "POST", "/api/preview", {{"method", "tile-deform"}})["job"]);
  call(client, "GET", preview["url"]);
  section["preview_seconds"] = secondsSince(started);
  started = std::chrono::steady_clock::now();
  json cut = waitForResult(server, call(client, "POST", "/api/cut", {{"axis", "x"}, {"position", 0.5}})["job"]);
  const Mesh opened = parseGltf(call(client, "GET", cut["url"])["bytes"].get<std::string>(), "the cut");
  section["cut_seconds"] = secondsSince(started);
  section["cut_vertices"] = opened.vertexCount();
  writeImage(out("studio_cut.png"), renderViews(opened, nullptr, {anglesAboutUp(render.up, cutViewAngles(0))}, render));
  server.stop();
  return section;
}

std::string studioMarkdown(const json& studio) {
  std::ostringstream md;
  md << "## Studio\n\n![the model cut open, as the studio's API answers it](studio_cut.png)\n\n"
     << "`texsynth studio MESH EXEMPLAR` serves a page to sketch curves on the model, see the field's glyphs, "
        "texture it and cut it open (docs/studio-api.md). Here its server ran in-process and was driven through "
        "its HTTP API on loopback as the page drives it (server start "
     << fixed3(studio["start_seconds"]) << " s, the display mesh " << studio["display_vertices"]
     << " vertices):\n\n| request | time |\n|---|---:|\n";
  if (studio.contains("curve_ms"))
    md << "| a sketch curve to the updated field and glyphs (median of 5) | "
       << fixed3(studio["curve_ms"]["median"].get<double>() / 1000) << " s |\n";
  md << "| exemplar to its textured preview (tile-deform, colours fetched) | " << fixed3(studio["preview_seconds"])
     << " s |\n| the model cut open at x = 0.5 (" << studio["cut_vertices"] << " vertices, as glTF) | "
     << fixed3(studio["cut_seconds"]) << " s |\n\n";
  return md.str();
}

}  // namespace texsynth::cli
