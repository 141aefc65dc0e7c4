// The studio's JSON API over HTTP: scene, sketch curves and glyphs, previews and cuts through the
// workers, exports, and answers to bad input (a 4xx with one message, the server still serving).
#include <gtest/gtest.h>

#include "studio_test_server.h"
#include "texsynth/core/error.h"
#include "texsynth/field/field_io.h"
#include "texsynth/field/sketch.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"
#include "texsynth/render/primitives.h"

namespace texsynth::studio::test {
namespace {

// A curve across the box's top face (z = 1), drawn as the page sends it.
nlohmann::json topCurve() {
  return {{"on", "surface"},
          {"tangent_axis", "x"},
          {"normal_axis", "z"},
          {"points", {{0.2, 0.3, 1.0}, {0.5, 0.45, 1.0}, {0.8, 0.7, 1.0}}}};
}

TEST(StudioApi, HealthCatalogAndScene) {
  TestStudio studio;
  EXPECT_EQ(studio.get("/api/health")["status"], "ok");
  const nlohmann::json catalog = studio.get("/api/catalog");
  for (const char* kind : {"meshes", "exemplars"})
    for (const auto& entry : catalog[kind]) {
      EXPECT_FALSE(entry.contains("path")) << "the page never sees paths";
      EXPECT_NE(entry["id"].get<std::string>().find('-'), std::string::npos);
    }
  const nlohmann::json scene = studio.get("/api/scene");
  EXPECT_EQ(scene["mesh"]["name"], "box");
  EXPECT_GE(scene["mesh"]["display_vertices"].get<int>(), 6000) << "subdivided for per-vertex colours";
  EXPECT_EQ(scene["field_revision"], 0);
  EXPECT_EQ(scene["texture"]["method"], "tile-deform");
}

TEST(StudioApi, CurvesTurnTheFieldAndTheGlyphs) {
  TestStudio studio;
  const nlohmann::json before = studio.get("/api/field/glyphs?across=8");
  ASSERT_GT(before["glyphs"].size(), 20u);  // on the display mesh's vertices
  const nlohmann::json added = studio.post("/api/sketch/curves", topCurve(), 201);
  const std::string id = added["id"];
  EXPECT_EQ(added["field_revision"], 1);
  EXPECT_GE(added["samples"].size(), 2u);
  for (const auto& p : added["samples"]) EXPECT_NEAR(p[2].get<float>(), 1.0f, 1e-4f) << "on the top face";
  const nlohmann::json after = studio.get("/api/field/glyphs?across=8");
  ASSERT_EQ(after["glyphs"].size(), before["glyphs"].size());
  int turned = 0;
  for (std::size_t i = 0; i < after["glyphs"].size(); ++i) {
    const auto &a = before["glyphs"][i]["x"], &b = after["glyphs"][i]["x"];
    if (a[0].get<float>() * b[0].get<float>() + a[1].get<float>() * b[1].get<float>() +
            a[2].get<float>() * b[2].get<float>() <
        0.999f)
      ++turned;
  }
  EXPECT_GT(turned, int(after["glyphs"].size()) / 2) << "the field follows the diagonal stroke";
  EXPECT_EQ(after["curves"][0]["id"], id);

  // The sketch reads back as the CLI's format; deleting the curve returns to the identity.
  const Sketch sketch = parseSketch(studio.get("/api/sketch").dump(), "sketch");
  EXPECT_EQ(sketch.curves.size(), 1u);
  EXPECT_EQ(studio.call("DELETE", "/api/sketch/curves/" + id, "", 200)["field_revision"], 2);
  EXPECT_EQ(studio.get("/api/field/glyphs?across=8")["glyphs"], before["glyphs"]);
  EXPECT_EQ(studio.call("DELETE", "/api/sketch/curves/" + id, "", 404)["error"], "curve '" + id + "': no such id");
}

TEST(StudioApi, BadRequestsGetOneMessageAndTheServerKeepsServing) {
  TestStudio studio;
  EXPECT_NE(studio.call("POST", "/api/sketch/curves", "{\"points\": [[0,0", 400)["error"].get<std::string>().find(
                "not valid JSON"),
            std::string::npos);
  nlohmann::json off = topCurve();
  off["points"] = {{0.2, 0.3, 3.0}, {0.5, 0.45, 3.0}};  // two units above the box
  EXPECT_FALSE(studio.post("/api/sketch/curves", off, 400)["error"].get<std::string>().empty());
  EXPECT_EQ(studio.get("/api/scene")["field_revision"], 0) << "a rejected curve changes nothing";
  nlohmann::json unknownKey = topCurve();
  unknownKey["colour"] = "red";
  studio.post("/api/sketch/curves", unknownKey, 400);
  studio.post("/api/sketch/curves", nlohmann::json::array(), 400);
  studio.post("/api/cut", {{"axis", "w"}, {"position", 0.5}}, 400);
  studio.post("/api/cut", {{"axis", "x"}, {"position", 1.5}}, 400);
  studio.post("/api/preview", {{"method", "magic"}}, 400);
  studio.post("/api/preview", {{"exemplar", "exemplar-999999"}}, 404);
  studio.post("/api/preview", {{"tiles", -1}}, 400);
  studio.post("/api/scene", {{"mesh", "../../etc/passwd"}}, 404);
  studio.post("/api/export", {{"format", "exe"}}, 400);
  studio.post("/api/export", {{"format", "vdb"}, {"resolution", 100000}}, 400);
  studio.get("/api/results/result-424242", 404);
  studio.get("/api/field/glyphs?across=lots", 400);
  EXPECT_EQ(studio.get("/api/no-such-route", 404)["error"], "no such route: GET /api/no-such-route");
  studio.get("/../../etc/passwd", 404);
  studio.get("/vendor/../../../etc/passwd", 404);
  EXPECT_EQ(studio.get("/api/health")["status"], "ok");
}

TEST(StudioApi, UploadsAreLimitedValidatedAndPrivate) {
  UploadLimits limits;
  limits.meshBytes = 4096;
  TestStudio studio(limits);
  const std::string goodMesh = encodeObj(makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
  const nlohmann::json mesh = studio.call("POST", "/api/uploads/mesh?format=obj&name=../../etc/passwd", goodMesh, 201);
  EXPECT_EQ(mesh["name"], "....etcpasswd") << "only harmless characters of the name are kept";
  EXPECT_EQ(mesh["id"], "upload-mesh-1");
  studio.post("/api/scene", {{"mesh", mesh["id"]}}, 200);

  const std::string truncated = goodMesh.substr(0, goodMesh.size() / 2) + "f 1 2 99\n";
  EXPECT_NE(
      studio.call("POST", "/api/uploads/mesh?format=obj&name=broken", truncated, 400)["error"].get<std::string>().find(
          "broken"),
      std::string::npos)
      << "the message names the upload, not the private file";
  studio.call("POST", "/api/uploads/mesh?format=obj", std::string(5000, 'v'), 413);
  studio.call("POST", "/api/uploads/mesh?format=../../x", goodMesh, 400);
  studio.call("POST", "/api/uploads/mesh", goodMesh, 400);
  studio.call("POST", "/api/uploads/mesh?format=obj", "", 400);
  const std::string png = encodePngBytes(texsynth::test::makeTestPattern(32, 32));
  EXPECT_EQ(studio.call("POST", "/api/uploads/exemplar?format=png&name=tiles", png, 201)["name"], "tiles");
  studio.call("POST", "/api/uploads/exemplar?format=png", png.substr(0, 40), 400);
  const nlohmann::json catalog = studio.get("/api/catalog");
  int uploads = 0;
  for (const char* kind : {"meshes", "exemplars"})
    for (const auto& entry : catalog[kind]) uploads += entry["group"] == "uploads";
  EXPECT_EQ(uploads, 2) << "rejected uploads leave nothing behind";
  EXPECT_EQ(studio.get("/api/health")["status"], "ok");
}

TEST(StudioApi, PreviewColoursEveryDisplayVertex) {
  TestStudio studio;
  const int vertices = studio.get("/api/scene")["mesh"]["display_vertices"];
  const nlohmann::json job = studio.post("/api/preview", {{"method", "tile-deform"}}, 202);
  const nlohmann::json result = studio.waitForResult(job["job"], "final");
  ASSERT_EQ(result["vertices"], vertices);
  const auto bytes = studio.client().Get(result["url"].get<std::string>().c_str());
  ASSERT_TRUE(bytes);
  EXPECT_EQ(bytes->body.size(), std::size_t(vertices) * 3);
  const char first = bytes->body[0];
  EXPECT_GT(std::count_if(bytes->body.begin(), bytes->body.end(), [first](char c) { return c != first; }), 1000)
      << "a texture, not one colour";
}

TEST(StudioApi, LazyPreviewComesFastThenRefinesWhatTheCameraSeesFirst) {
  TestStudio studio({}, 32);
  studio.post("/api/sketch/curves", topCurve(), 201);
  studio.post("/api/preview", {{"method", "lazy"}, {"camera", {0.5, 0.5}}}, 400);
  const nlohmann::json job =
      studio.post("/api/preview", {{"method", "lazy"}, {"tiles", 1}, {"camera", {0.5, 0.5, 6.0}}}, 202);
  const nlohmann::json fast = studio.waitForResult(job["job"], "fast");
  EXPECT_EQ(fast["method"], "tile-deform");
  const nlohmann::json visible = studio.waitForResult(job["job"], "visible");
  const nlohmann::json final = studio.waitForResult(job["job"], "final");
  EXPECT_EQ(final["method"], "lazy");
  EXPECT_EQ(final["field_revision"], 1);
  // Vertices facing the camera (the top face, z = 1) already have their final colours.
  const auto get = [&](const nlohmann::json& result) {
    return studio.client().Get(result["url"].get<std::string>().c_str())->body;
  };
  const std::string fastBytes = get(fast), visibleBytes = get(visible), finalBytes = get(final);
  ASSERT_EQ(visibleBytes.size(), finalBytes.size());
  std::size_t refined = 0, kept = 0, differ = 0;
  for (std::size_t i = 0; i < finalBytes.size(); ++i) {
    refined += visibleBytes[i] == finalBytes[i] && visibleBytes[i] != fastBytes[i];
    kept += visibleBytes[i] == fastBytes[i] && visibleBytes[i] != finalBytes[i];
    differ += finalBytes[i] != fastBytes[i];
  }
  EXPECT_GT(refined, differ / 10) << "the side facing the camera is refined first";
  EXPECT_GT(kept, differ / 2) << "the rest waits for the final stage";
}

TEST(StudioApi, ANewerJobSupersedesTheOlderInItsLane) {
  TestStudio studio({}, 32);
  const std::string first = studio.post("/api/cut", {{"axis", "x"}, {"position", 0.3}, {"method", "lazy"}}, 202)["job"];
  const std::string second =
      studio.post("/api/cut", {{"axis", "x"}, {"position", 0.6}, {"method", "lazy"}}, 202)["job"];
  const nlohmann::json result = studio.waitForResult(second);
  EXPECT_FLOAT_EQ(result["position"].get<float>(), 0.6f);
  studio.server().jobs().waitIdle();
  std::string firstState;
  for (const StudioEvent& event : studio.events())
    if (event.type == "job" && event.data["id"] == first) firstState = event.data["state"];
  EXPECT_TRUE(firstState == "superseded" || firstState == "cancelled" || firstState == "done") << firstState;
  for (const StudioEvent& event : studio.events()) {
    if (event.type == "result") {
      EXPECT_NE(event.data["job"], first) << "a stale cut never finished after the newer";
    }
  }
}

TEST(StudioApi, CutAndExportsUseTheProjectsFormats) {
  TestStudio studio;
  texsynth::test::TempDir dir;
  studio.post("/api/sketch/curves", topCurve(), 201);
  const nlohmann::json cut =
      studio.waitForResult(studio.post("/api/cut", {{"axis", "z"}, {"position", 0.5}}, 202)["job"]);
  const auto glb = studio.client().Get(cut["url"].get<std::string>().c_str());
  ASSERT_TRUE(glb);
  const Mesh opened = parseGltf(glb->body, "cut.glb");
  EXPECT_EQ(opened.colors.size(), opened.positions.size());
  Box3f bounds = opened.bounds();
  EXPECT_LE(bounds.max.z(), 0.55f) << "the +z half is removed (triangles by their centroids)";

  const auto exported = [&](const std::string& format) {
    const auto answer =
        studio.client().Post("/api/export", nlohmann::json{{"format", format}}.dump(), "application/json");
    EXPECT_TRUE(answer && answer->status == 200) << format;
    return answer ? answer->body : std::string();
  };
  EXPECT_EQ(parseGltf(exported("glb"), "model.glb").positions.size(),
            std::size_t(studio.get("/api/scene")["mesh"]["display_vertices"].get<int>()));
  EXPECT_EQ(decodeField(exported("tsfield"), "field").rotations.grid().nodeCount() > 0, true);
  EXPECT_EQ(parseSketch(exported("sketch"), "sketch").curves.size(), 1u);
  texsynth::test::writeBytes(dir.file("v.vdb"), exported("vdb"));
  EXPECT_EQ(readVolume(dir.file("v.vdb")).nx, 64);
}

TEST(StudioApi, EventStreamDeliversJobStates) {
  TestStudio studio;
  std::string received;
  std::atomic<bool> done{false};
  std::thread reader([&] {
    httplib::Client client("127.0.0.1", studio.port());
    client.Get("/api/events", [&](const char* data, std::size_t length) {
      received.append(data, length);
      return received.find("\"state\":\"done\"") == std::string::npos;
    });
    done = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  studio.post("/api/preview", {{"method", "tile-deform"}}, 202);
  reader.join();
  EXPECT_TRUE(done);
  EXPECT_NE(received.find("event: result"), std::string::npos);
  EXPECT_NE(received.find("event: job"), std::string::npos);
}

}  // namespace
}  // namespace texsynth::studio::test
