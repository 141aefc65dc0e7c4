// Garbage the studio refuses at the door, each with a 400 (or a failed start) that says what is wrong:
// meshes with nothing to texture, a scene request that asks for nothing, a page folder that is not there.
#include <gtest/gtest.h>

#include "studio_test_server.h"
#include "texsynth/core/error.h"

namespace texsynth::studio::test {
namespace {

std::string uploadError(TestStudio& studio, const std::string& name, const std::string& obj) {
  const nlohmann::json answer = studio.call("POST", "/api/uploads/mesh?format=obj&name=" + name, obj, 400);
  return answer.value("error", "");
}

TEST(StudioValidation, MeshesWithoutExtentOrAreaAreRefused) {
  TestStudio studio;
  const std::string point = uploadError(studio, "dot", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
  EXPECT_NE(point.find("dot"), std::string::npos) << point;
  EXPECT_NE(point.find("one point"), std::string::npos) << point;
  const std::string line = uploadError(studio, "line", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  EXPECT_NE(line.find("line"), std::string::npos) << line;
  EXPECT_NE(line.find("zero area"), std::string::npos) << line;
  int uploads = 0;
  const nlohmann::json catalog = studio.get("/api/catalog");
  for (const auto& entry : catalog["meshes"]) uploads += entry["group"] == "uploads";
  EXPECT_EQ(uploads, 0);
}

TEST(StudioValidation, ASceneRequestMustNameAMeshOrAnExemplar) {
  TestStudio studio;
  for (const char* body : {"", "{}"}) {
    const nlohmann::json answer = studio.call("POST", "/api/scene", body, 400);
    EXPECT_NE(answer.value("error", "").find("\"mesh\""), std::string::npos) << "'" << body << "': " << answer;
  }
  EXPECT_EQ(studio.events().size(), 0u) << "no scene event for a request that changed nothing";
}

TEST(StudioValidation, TheStudioRefusesToStartWithoutItsPageFolder) {
  texsynth::test::TempDir dir;
  for (const std::string& webRoot : {dir.file("missing"), dir.path()}) {  // absent; present without index.html
    StudioOptions options;
    options.port = 0;
    options.webRoot = webRoot;
    options.cacheDirectory = dir.file("cache");
    try {
      StudioServer server(options);
      ADD_FAILURE() << "started with --web-root " << webRoot;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), webRoot);
      EXPECT_NE(std::string(e.what()).find("index.html"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace texsynth::studio::test
