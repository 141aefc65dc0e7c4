// The studio test fixture: a server on a free port over generated data.
#include "studio_test_server.h"

#include <gtest/gtest.h>

#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"

namespace texsynth::studio::test {

TestStudio::TestStudio(const UploadLimits& limits, int exemplarSide) {
  writeMesh(dir_.file("box.ply"), makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
  writeImage(dir_.file("pattern.png"), texsynth::test::makeTestPattern(exemplarSide, exemplarSide));
  StudioOptions options;
  options.port = 0;
  options.limits = limits;
  options.displayVertices = 6000;  // small models keep the suite fast (sanitizers included)
  options.cacheDirectory = dir_.file("cache");
  options.mesh = dir_.file("box.ply");
  options.exemplar = dir_.file("pattern.png");
  server_ = std::make_unique<StudioServer>(options);
  port_ = server_->start();
  client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
  client_->set_read_timeout(120, 0);
}

TestStudio::~TestStudio() {
  server_->stop();
}

nlohmann::json TestStudio::call(const std::string& method, const std::string& path, const std::string& body,
                                int status) {
  httplib::Result result = method == "GET"      ? client_->Get(path.c_str())
                           : method == "DELETE" ? client_->Delete(path.c_str())
                           : method == "PUT"    ? client_->Put(path.c_str(), body, "application/json")
                                                : client_->Post(path.c_str(), body, "application/json");
  if (!result) {
    ADD_FAILURE() << method << " " << path << ": no answer";
    return {};
  }
  EXPECT_EQ(result->status, status) << method << " " << path << ": " << result->body;
  if (result->get_header_value("Content-Type") != "application/json") return {{"bytes", result->body}};
  return nlohmann::json::parse(result->body);
}

nlohmann::json TestStudio::waitForResult(const std::string& job, const std::string& stage) {
  const auto event = server_->events().waitFor(
      [&](const StudioEvent& e) {
        return (e.type == "result" && e.data["job"] == job && (stage.empty() || e.data["stage"] == stage)) ||
               (e.type == "job" && e.data["id"] == job && e.data["state"] == "failed");
      },
      std::chrono::minutes(5));
  if (!event || event->type != "result") {
    ADD_FAILURE() << "no result for " << job << (event ? ": " + event->data.dump() : "");
    return {};
  }
  return event->data;
}

std::vector<StudioEvent> TestStudio::events() {
  return server_->events().waitAfter(0, std::chrono::milliseconds(0));
}

}  // namespace texsynth::studio::test
