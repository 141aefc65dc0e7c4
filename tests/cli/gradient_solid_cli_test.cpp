// `texsynth info FILE.tsgs`: what a gradient solid file holds, and one clear line for a bad one.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "texsynth/gradient/gradient_solid_file.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;

namespace {

// A 32^3 RGB solid (9^3 control points) with two regions and two boundary control points.
GradientSolid smallSolid() {
  GradientSolid solid = GradientSolid::zeros({32, 32, 32}, 3);
  for (std::size_t i = 0; i < solid.positive.size(); ++i)
    if (i % 12 < 3) solid.positive[i] = 0.25f + 0.5f * float(i % 12) / 2.0f * float(i % 7) / 6.0f;
  const auto n = std::size_t(solid.controlCount());
  solid.distance.assign(4 * n, 2.0f);
  solid.negativeIndex.assign(n, -1);
  solid.negativeIndex[5] = 1, solid.negativeIndex[40] = 0;
  solid.negative.assign(2 * 12, 0.1f);
  return solid;
}

TEST(GradientSolidCli, InfoDescribesTheSolidAsJson) {
  test::TempDir dir;
  const std::string path = dir.file("solid.tsgs");
  writeGradientSolid(path, smallSolid());
  RunResult r = runTexsynth("info " + path + " --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_EQ(d["kind"], "gradient solid");
  EXPECT_EQ(d["voxels"], nlohmann::json::array({32, 32, 32}));
  EXPECT_EQ(d["controls"], nlohmann::json::array({9, 9, 9}));
  EXPECT_EQ(d["spacing"], 4);
  EXPECT_EQ(d["channels"], 3);
  EXPECT_EQ(d["regions"], true);
  EXPECT_EQ(d["boundary_controls"], 2);
  EXPECT_EQ(d["detail"], false);
  const auto bytes = std::filesystem::file_size(path);
  EXPECT_EQ(d["file_bytes"], bytes);
  EXPECT_EQ(d["raw_volume_bytes"], 32 * 32 * 32 * 3);
  EXPECT_NEAR(d["percent_of_raw"].get<double>(), 100.0 * double(bytes) / (32 * 32 * 32 * 3), 1e-9);
  ASSERT_EQ(d["value_ranges"].size(), 3u);
  EXPECT_FLOAT_EQ(d["value_ranges"][0]["min"].get<float>(), 0.1f);  // the negative sets' value
  EXPECT_FLOAT_EQ(d["value_ranges"][0]["max"].get<float>(), 0.25f);
  EXPECT_GT(d["value_ranges"][2]["max"].get<double>(), 0.5);
}

TEST(GradientSolidCli, InfoPrintsTheSolidForPeople) {
  test::TempDir dir;
  const std::string path = dir.file("solid.tsgs");
  writeGradientSolid(path, smallSolid());
  RunResult r = runTexsynth("info " + path, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* text : {": gradient solid", "controls", "[9,9,9]", "percent_of_raw", "value_ranges"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text << " in " << r.out;
}

TEST(GradientSolidCli, CorruptedFileGivesOneClearLine) {
  test::TempDir dir;
  const std::string path = dir.file("solid.tsgs");
  std::string bytes = encodeGradientSolid(smallSolid());
  bytes[bytes.size() / 2] ^= 0x04;
  test::writeBytes(path, bytes);
  test::expectOneLineError(runTexsynth("info " + path, dir), 1, path + ": CRC-32 mismatch");
  test::writeBytes(path, bytes.substr(0, 100));
  test::expectOneLineError(runTexsynth("info " + path, dir), 1, "truncated");
}

}  // namespace
