// Request bodies are limited per route (docs/studio-api.md), whatever their content type: curl's
// default form type (application/x-www-form-urlencoded, `curl -d`) gets the same limits as any.
#include <gtest/gtest.h>

#include "studio_test_server.h"
#include "texsynth/core/random.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"

namespace texsynth::studio::test {
namespace {

constexpr const char* kForm = "application/x-www-form-urlencoded";

// A PNG of noise, so that it stays about 3 bytes a pixel: 600x600 is about 1 MiB.
std::string noisePng(int side) {
  Image image(side, side, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = uniform01(hashKey(7, i));
  return encodePngBytes(image);
}

// A curve across the box's top face with `points` points (about 35 bytes of JSON each).
std::string longCurve(int points) {
  nlohmann::json line = nlohmann::json::array();
  for (int i = 0; i < points; ++i) {
    const double t = 0.2 + 0.6 * i / (points - 1);
    line.push_back({t, 0.3 + 0.4 * (t - 0.2) / 0.6, 1.0});
  }
  return nlohmann::json{{"on", "surface"}, {"tangent_axis", "x"}, {"normal_axis", "z"}, {"points", line}}.dump();
}

TEST(StudioBodyLimits, FormEncodedUploadsOfAMebibyteAreAccepted) {
  TestStudio studio;
  const std::string png = noisePng(600);
  ASSERT_GT(png.size(), std::size_t(1) << 20);
  const auto answer = studio.client().Post("/api/uploads/exemplar?format=png&name=noise", png, kForm);
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->status, 201) << answer->body;
}

TEST(StudioBodyLimits, JsonBodiesOfTwentyKilobytesAreAccepted) {
  TestStudio studio;
  const std::string curve = longCurve(600);
  ASSERT_GT(curve.size(), 20000u);
  for (const char* type : {"application/json", kForm}) {
    const auto answer = studio.client().Post("/api/sketch/curves", curve, type);
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->status, 201) << type << ": " << answer->body;
  }
}

TEST(StudioBodyLimits, EachRouteAnswers413OverItsOwnLimit) {
  UploadLimits limits;
  limits.meshBytes = 4096;
  limits.exemplarBytes = 8192;
  TestStudio studio(limits);
  for (const char* type : {"application/octet-stream", kForm}) {
    const auto mesh = studio.client().Post("/api/uploads/mesh?format=obj", std::string(5000, 'v'), type);
    ASSERT_TRUE(mesh);
    EXPECT_EQ(mesh->status, 413) << type << ": " << mesh->body;
    EXPECT_NE(mesh->body.find("4096"), std::string::npos) << "the message gives the limit: " << mesh->body;
    const auto exemplar = studio.client().Post("/api/uploads/exemplar?format=png", std::string(9000, 'x'), type);
    ASSERT_TRUE(exemplar);
    EXPECT_EQ(exemplar->status, 413) << type << ": " << exemplar->body;
  }
  // A mesh-sized body is too much for a route that takes JSON (at most 4 MiB).
  limits = {};
  TestStudio defaults(limits);
  const std::string tooMuch((std::size_t(4) << 20) + 1, ' ');
  for (const char* type : {"application/json", kForm}) {
    const auto json = defaults.client().Post("/api/scene", tooMuch, type);
    ASSERT_TRUE(json);
    EXPECT_EQ(json->status, 413) << type << ": " << json->body.substr(0, 200);
  }
  EXPECT_EQ(defaults.get("/api/health")["status"], "ok") << "the server still serves";
}

}  // namespace
}  // namespace texsynth::studio::test
