// A known path asked with a method it does not take gets 405 and the methods it does take (Allow);
// an unknown path gets 404; either way the connection goes on serving.
#include <gtest/gtest.h>

#include <chrono>

#include "studio_test_server.h"
#include "test_support.h"

namespace texsynth::studio::test {
namespace {

httplib::Result send(httplib::Client& client, const std::string& method, const std::string& path,
                     const std::string& body = "") {
  if (method == "GET") return client.Get(path.c_str());
  if (method == "DELETE") return client.Delete(path.c_str(), body, "application/json");
  if (method == "PUT") return client.Put(path.c_str(), body, "application/json");
  if (method == "PATCH") return client.Patch(path.c_str(), body, "application/json");
  return client.Post(path.c_str(), body, "application/json");
}

TEST(StudioMethods, AKnownPathWithTheWrongMethodIs405WithAllow) {
  TestStudio studio;
  const struct {
    const char *method, *path, *allow;
  } cases[] = {{"POST", "/api/health", "GET, HEAD"},
               {"DELETE", "/api/scene", "GET, HEAD, POST"},
               {"GET", "/api/preview", "POST"},
               {"PUT", "/api/export", "POST"},
               {"PATCH", "/api/sketch", "GET, HEAD, PUT"},
               {"GET", "/api/sketch/curves", "POST"},
               {"GET", "/api/sketch/curves/curve-1", "DELETE"},
               {"POST", "/api/exemplars/exemplar-1/image", "GET, HEAD"},
               {"DELETE", "/api/uploads/mesh", "POST"},
               {"POST", "/api/events", "GET, HEAD"}};
  for (const auto& c : cases) {
    const auto answer = send(studio.client(), c.method, c.path, "{\"a\": 1}");
    ASSERT_TRUE(answer) << c.method << " " << c.path;
    EXPECT_EQ(answer->status, 405) << c.method << " " << c.path << ": " << answer->body;
    EXPECT_EQ(answer->get_header_value("Allow"), c.allow) << c.method << " " << c.path;
    EXPECT_NE(answer->body.find(c.allow), std::string::npos) << answer->body;
  }
  for (const char* method : {"GET", "POST", "PUT", "DELETE"}) {
    const auto answer = send(studio.client(), method, "/api/no-such-route", "{}");
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->status, 404) << method << ": " << answer->body;
    EXPECT_FALSE(answer->has_header("Allow"));
  }
  EXPECT_EQ(studio.get("/api/health")["status"], "ok") << "the same connection still serves";
}

TEST(StudioMethods, ABodilessPostIsAnsweredAtOnce) {
  TestStudio studio;
  // curl -X POST sends neither Content-Length nor a chunked body: HTTP/1.1 says there is no body.
  const auto started = std::chrono::steady_clock::now();
  const std::string answer = texsynth::test::loopbackExchange(
      studio.port(), "POST /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(2)) << "no wait for a body";
  EXPECT_EQ(answer.rfind("HTTP/1.1 405", 0), 0u) << answer;
  EXPECT_NE(answer.find("Allow: GET, HEAD\r\n"), std::string::npos) << answer;
  const std::string scene = texsynth::test::loopbackExchange(
      studio.port(), "POST /api/scene HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(scene.rfind("HTTP/1.1 400", 0), 0u) << scene;
}

}  // namespace
}  // namespace texsynth::studio::test
