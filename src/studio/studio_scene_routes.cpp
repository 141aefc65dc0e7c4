// Routes for what is being textured: the catalog and uploads, the scene (mesh and exemplar), the
// sketch curves and the field's glyphs.
#include <chrono>

#include "studio_state.h"
#include "texsynth/core/error.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth::studio {

namespace {

nlohmann::json entryJson(const CatalogEntry& entry) {
  return {{"id", entry.id}, {"name", entry.name}, {"group", entry.group}};
}

nlohmann::json sceneJson(const StudioState& state) {
  nlohmann::json scene = {{"exemplar", state.texture.exemplarId}, {"texture", state.texture.toJson()}};
  if (!state.scene) return scene;
  const StudioScene& s = *state.scene;
  const Box3f& box = s.bounds();
  nlohmann::json curves = nlohmann::json::array();
  for (const SceneCurve& c : s.curves()) curves.push_back(c.id);
  scene["mesh"] = {{"id", s.meshId()},
                   {"name", s.meshName()},
                   {"vertices", s.mesh().vertexCount()},
                   {"triangles", s.mesh().triangleCount()},
                   {"display_vertices", s.display().vertexCount()},
                   {"bounds", {{box.min.x(), box.min.y(), box.min.z()}, {box.max.x(), box.max.y(), box.max.z()}}}};
  scene["curves"] = curves;
  scene["field_revision"] = s.revision();
  const FieldGrid& grid = s.fieldGrid();
  scene["field_grid"] = {grid.nodes.x(), grid.nodes.y(), grid.nodes.z()};
  return scene;
}

// One curve in the sketch file's curve format (docs/sketch-format.md), parsed by the same reader.
SketchCurve parseCurve(const nlohmann::json& body) {
  if (!body.is_object()) throw HttpError(400, "give one curve as a JSON object");
  const Sketch sketch = parseSketch(nlohmann::json{{"curves", {body}}}.dump(), "curve");
  return sketch.curves.front();
}

std::string queryValue(const httplib::Request& request, const std::string& key, const std::string& fallback = {}) {
  return request.has_param(key) ? request.get_param_value(key) : fallback;
}

void upload(StudioRouter& router, StudioState& state, const std::string& route, bool mesh) {
  const std::size_t limit = mesh ? state.options.limits.meshBytes : state.options.limits.exemplarBytes;
  router.post(route, limit, [&state, mesh](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      if (!request.has_param("format")) throw HttpError(400, "give the file type: ?format=EXT");
      const std::string format = request.get_param_value("format"), name = queryValue(request, "name");
      const CatalogEntry entry = mesh ? state.catalog.uploadMesh(request.body, format, name)
                                      : state.catalog.uploadExemplar(request.body, format, name);
      sendJson(response, entryJson(entry), 201);
    });
  });
}

}  // namespace

void addSceneRoutes(StudioRouter& router, StudioState& state) {
  const std::size_t json = state.options.limits.jsonBytes;
  router.get("/api/catalog", [&state](const httplib::Request&, httplib::Response& response) {
    nlohmann::json meshes = nlohmann::json::array(), exemplars = nlohmann::json::array();
    for (const CatalogEntry& e : state.catalog.meshes()) meshes.push_back(entryJson(e));
    for (const CatalogEntry& e : state.catalog.exemplars()) exemplars.push_back(entryJson(e));
    sendJson(response, {{"meshes", meshes}, {"exemplars", exemplars}});
  });
  upload(router, state, "/api/uploads/mesh", true);
  upload(router, state, "/api/uploads/exemplar", false);

  router.get(R"(/api/exemplars/([A-Za-z0-9-]+)/image)",
             [&state](const httplib::Request& request, httplib::Response& response) {
               answer(response, [&] {
                 const CatalogEntry entry = state.catalog.exemplar(request.matches[1]);
                 response.set_content(encodePngBytes(readImage(entry.path)), "image/png");
               });
             });

  router.get("/api/scene", [&state](const httplib::Request&, httplib::Response& response) {
    std::lock_guard<std::mutex> lock(state.mutex);
    sendJson(response, sceneJson(state));
  });
  router.post("/api/scene", json, [&state](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      const nlohmann::json body = jsonBody(request);
      if (!body.is_object() || (!body.contains("mesh") && !body.contains("exemplar")))
        throw HttpError(400, "give {\"mesh\": ID} and/or {\"exemplar\": ID}");
      for (const auto& [key, value] : body.items())
        if ((key != "mesh" && key != "exemplar") || !value.is_string())
          throw HttpError(400, "'" + key + "': give {\"mesh\": ID} and/or {\"exemplar\": ID} (ids are strings)");
      std::shared_ptr<StudioScene> scene;
      if (body.contains("mesh")) {  // loaded outside the lock: a big mesh takes a moment
        const CatalogEntry entry = state.catalog.mesh(body["mesh"].get<std::string>());
        scene =
            std::make_shared<StudioScene>(entry.id, entry.name, readMesh(entry.path), state.options.displayVertices);
      }
      std::lock_guard<std::mutex> lock(state.mutex);
      if (body.contains("exemplar")) state.catalog.exemplar(body["exemplar"].get<std::string>());  // 404 if unknown
      if (scene) state.scene = scene, ++state.sceneSerial;
      if (body.contains("exemplar")) state.texture.exemplarId = body["exemplar"].get<std::string>();
      state.keepSceneInUse();
      const nlohmann::json now = sceneJson(state);
      state.events.publish("scene", now);
      sendJson(response, now);
    });
  });
  router.get("/api/mesh.glb", [&state](const httplib::Request&, httplib::Response& response) {
    answer(response, [&] {
      std::shared_ptr<StudioScene> scene;
      {
        std::lock_guard<std::mutex> lock(state.mutex);
        scene = state.requireScene();
      }
      response.set_content(encodeGltf(scene->display(), true), "model/gltf-binary");
    });
  });

  router.get("/api/sketch", [&state](const httplib::Request&, httplib::Response& response) {
    answer(response, [&] {
      std::lock_guard<std::mutex> lock(state.mutex);
      response.set_content(encodeSketch(state.requireScene()->sketch()), "application/json");
    });
  });
  router.put("/api/sketch", json, [&state](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      const Sketch sketch = parseSketch(request.body, "sketch");
      std::lock_guard<std::mutex> lock(state.mutex);
      StudioScene& scene = *state.requireScene();
      scene.replaceSketch(sketch);
      nlohmann::json ids = nlohmann::json::array();
      for (const SceneCurve& c : scene.curves()) ids.push_back(c.id);
      const nlohmann::json body = {{"curves", ids}, {"field_revision", scene.revision()}};
      state.events.publish("field", body);
      sendJson(response, body);
    });
  });
  router.post("/api/sketch/curves", json, [&state](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      const SketchCurve curve = parseCurve(jsonBody(request));
      const auto started = std::chrono::steady_clock::now();
      std::lock_guard<std::mutex> lock(state.mutex);
      StudioScene& scene = *state.requireScene();
      const SceneCurve& added = scene.addCurve(curve);
      nlohmann::json samples = nlohmann::json::array();
      for (const Vec3f& p : added.samples) samples.push_back({p.x(), p.y(), p.z()});
      const nlohmann::json body = {
          {"id", added.id},
          {"samples", samples},
          {"field_revision", scene.revision()},
          {"constrained_nodes", added.update.constrainedNodes},
          {"solve", {{"iterations", added.update.solve.iterations}, {"seconds", added.update.solve.seconds}}},
          {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()}};
      state.events.publish("field", {{"field_revision", scene.revision()}, {"added", added.id}});
      sendJson(response, body, 201);
    });
  });
  router.del(R"(/api/sketch/curves/([A-Za-z0-9-]+))", [&state](const httplib::Request& request,
                                                               httplib::Response& response) {
    answer(response, [&] {
      std::lock_guard<std::mutex> lock(state.mutex);
      StudioScene& scene = *state.requireScene();
      scene.removeCurve(request.matches[1]);
      const nlohmann::json body = {{"removed", std::string(request.matches[1])}, {"field_revision", scene.revision()}};
      state.events.publish("field", body);
      sendJson(response, body);
    });
  });
  router.get("/api/field/glyphs", [&state](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      int across = 14;
      if (request.has_param("across")) {
        try {
          across = std::stoi(request.get_param_value("across"));
        } catch (const std::exception&) {
          throw HttpError(400, "across: give a whole number in [2, 100]");
        }
        if (across < 2 || across > 100) throw HttpError(400, "across: give a whole number in [2, 100]");
      }
      std::lock_guard<std::mutex> lock(state.mutex);
      sendJson(response, state.requireScene()->glyphs(across));
    });
  });
}

}  // namespace texsynth::studio
