#pragma once
// A studio server on a free loopback port over a box mesh and a test-pattern exemplar written to a
// temporary folder, with an HTTP client for it.
#include <httplib.h>
// httplib brings <resolv.h>, whose `_res` macro breaks Eigen's products (a parameter of that name).
#undef _res

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "test_support.h"
#include "texsynth/studio/event_hub.h"
#include "texsynth/studio/job_lanes.h"
#include "texsynth/studio/studio_server.h"

namespace texsynth::studio::test {

class TestStudio {
 public:
  // `limits` for the upload tests; the exemplar is `exemplarSide` pixels square.
  explicit TestStudio(const UploadLimits& limits = {}, int exemplarSide = 48);
  ~TestStudio();

  httplib::Client& client() { return *client_; }
  StudioServer& server() { return *server_; }
  int port() const { return port_; }
  // The body of a JSON answer, failing the test on a status other than `status`.
  nlohmann::json call(const std::string& method, const std::string& path, const std::string& body, int status);
  nlohmann::json get(const std::string& path, int status = 200) { return call("GET", path, "", status); }
  nlohmann::json post(const std::string& path, const nlohmann::json& body, int status) {
    return call("POST", path, body.dump(), status);
  }
  // Waits for the job's "result" event of `stage` (or any stage if empty) and returns its data.
  nlohmann::json waitForResult(const std::string& job, const std::string& stage = "");
  // Every event published so far.
  std::vector<StudioEvent> events();

 private:
  texsynth::test::TempDir dir_;
  std::unique_ptr<StudioServer> server_;
  std::unique_ptr<httplib::Client> client_;
  int port_ = 0;
};

}  // namespace texsynth::studio::test
