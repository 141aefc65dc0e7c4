// Exports as `texsynth studio` makes them: the command runs inside the run's OutputBatch (main.cpp),
// so a writer the server reads back must not wait for the batch's commit at shutdown.
#include <gtest/gtest.h>

#include "studio_test_server.h"
#include "texsynth/core/output_batch.h"
#include "texsynth/io/volume_io.h"

namespace texsynth::studio::test {
namespace {

TEST(StudioExport, VdbExportReadsBackWhatItWroteInsideTheRunsBatch) {
  TestStudio studio;
  texsynth::test::TempDir dir;
  OutputBatch run;  // as main.cpp wraps every command, the studio included
  const auto answer = studio.client().Post("/api/export", R"({"format": "vdb", "resolution": 16})", "application/json");
  ASSERT_TRUE(answer);
  ASSERT_EQ(answer->status, 200) << answer->body;
  EXPECT_EQ(answer->body.find("texsynth-scratch"), std::string::npos);
  // OpenVDB files open with the magic number 0x56444220 ("VDB "), little-endian.
  ASSERT_GT(answer->body.size(), 8u);
  EXPECT_EQ(answer->body.substr(0, 4), std::string(" BDV"));
  texsynth::test::writeBytes(dir.file("export.vdb"), answer->body);
  EXPECT_EQ(readVolume(dir.file("export.vdb")).nx, 16);
  // Nothing of the server's is left for the run to move into place at shutdown.
  EXPECT_EQ(run.stagedCount(), 0u);
  EXPECT_NO_THROW(run.commit());
}

}  // namespace
}  // namespace texsynth::studio::test
