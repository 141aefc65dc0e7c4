// Error answers speak of the request and the user's uploads, never of the library that parsed them
// or the private files the server keeps.
#include <gtest/gtest.h>

#include "studio_test_server.h"

namespace texsynth::studio::test {
namespace {

void expectNoInternals(const std::string& message) {
  for (const char* internal : {"json.exception", "texsynth-scratch", "texsynth-tmp", "/tmp/"})
    EXPECT_EQ(message.find(internal), std::string::npos) << message;
}

TEST(StudioErrorMessages, MalformedJsonIsNamedPlainlyWithItsPlace) {
  TestStudio studio;
  const std::pair<const char*, const char*> routes[] = {{"POST", "/api/scene"},         {"POST", "/api/preview"},
                                                        {"POST", "/api/cut"},           {"POST", "/api/export"},
                                                        {"POST", "/api/sketch/curves"}, {"PUT", "/api/sketch"}};
  for (const auto& [method, path] : routes) {
    const std::string error = studio.call(method, path, "{\"points\": [[0,0", 400).value("error", "");
    expectNoInternals(error);
    EXPECT_NE(error.find("not valid JSON"), std::string::npos) << path << ": " << error;
    EXPECT_NE(error.find("line 1, column"), std::string::npos) << path << ": " << error;
  }
}

TEST(StudioErrorMessages, RejectedUploadsAreNamedByTheUsersName) {
  TestStudio studio;
  for (const char* format : {"obj", "ply", "off", "stl", "glb"}) {
    const std::string error =
        studio.call("POST", std::string("/api/uploads/mesh?name=mine&format=") + format, "garbage\n", 400)
            .value("error", "");
    expectNoInternals(error);
    EXPECT_NE(error.find("mine"), std::string::npos) << format << ": " << error;
  }
  for (const char* format : {"png", "jpg", "exr", "pat"}) {
    const std::string error =
        studio.call("POST", std::string("/api/uploads/exemplar?name=mine&format=") + format, "garbage\n", 400)
            .value("error", "");
    expectNoInternals(error);
    EXPECT_NE(error.find("mine"), std::string::npos) << format << ": " << error;
  }
}

}  // namespace
}  // namespace texsynth::studio::test
