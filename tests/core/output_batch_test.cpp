// All-or-nothing outputs: staged files appear only on commit, a batch that does not commit
// leaves everything as it was, and a commit that fails part way puts back what it replaced.
#include "texsynth/core/output_batch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/temporary_files.h"

using namespace texsynth;
namespace fs = std::filesystem;

namespace {

std::string contents(const std::string& path) {
  return fs::exists(path) ? readFileBytes(path) : "<missing>";
}

// Every file in `dir`, so a test can see that nothing was left behind.
std::vector<std::string> listing(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST(OutputBatch, StagedFilesAppearOnlyOnCommit) {
  test::TempDir dir;
  test::writeBytes(dir.file("a.txt"), "old a");
  OutputBatch batch;
  writeFileAtomically(dir.file("a.txt"), "new a");
  writeFileAtomically(dir.file("b.txt"), "new b");
  EXPECT_EQ(contents(dir.file("a.txt")), "old a");
  EXPECT_EQ(contents(dir.file("b.txt")), "<missing>");
  EXPECT_EQ(batch.stagedCount(), 2u);
  batch.commit();
  EXPECT_EQ(contents(dir.file("a.txt")), "new a");
  EXPECT_EQ(contents(dir.file("b.txt")), "new b");
  EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(OutputBatch, WithoutCommitNothingChangesAndNothingIsLeft) {
  test::TempDir dir;
  test::writeBytes(dir.file("good.png"), "good");
  {
    OutputBatch batch;
    writeFileAtomically(dir.file("good.png"), "replacement");
    batch.createDirectories(dir.file("new/deeper"));
    writeFileAtomically(dir.file("new/deeper/report.md"), "report");
    EXPECT_THROW(writeFileAtomically(dir.file("missing/x.nrrd"), "x"), OutputError);
  }  // an error unwound the run
  EXPECT_EQ(contents(dir.file("good.png")), "good");
  EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"good.png"}));
}

TEST(OutputBatch, FailedCommitRestoresWhatItReplaced) {
  test::TempDir dir;
  test::writeBytes(dir.file("first.txt"), "old first");
  OutputBatch batch;
  writeFileAtomically(dir.file("first.txt"), "new first");
  writeFileAtomically(dir.file("second.txt"), "new second");
  writeFileAtomically(dir.file("third.txt"), "new third");
  // Something takes the second name before the commit: a non-empty directory cannot be replaced.
  fs::create_directories(dir.file("second.txt/occupied"));
  EXPECT_THROW(batch.commit(), OutputError);
  EXPECT_EQ(contents(dir.file("first.txt")), "old first");
  EXPECT_EQ(contents(dir.file("third.txt")), "<missing>");
  EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"first.txt", "second.txt"}));
}

TEST(OutputBatch, CachesAreWrittenAtOnceEvenInsideABatch) {
  test::TempDir dir;
  OutputBatch batch;
  writeFileAtomically(dir.file("cache.bin"), "cache", Staging::Immediately);
  EXPECT_EQ(contents(dir.file("cache.bin")), "cache");
  EXPECT_EQ(batch.stagedCount(), 0u);
}

TEST(OutputBatch, OneAtATime) {
  OutputBatch batch;
  EXPECT_EQ(OutputBatch::active(), &batch);
  EXPECT_THROW(OutputBatch another, InternalError);
}

TEST(OutputBatch, AWriterThatFailsLeavesNoTemporary) {
  test::TempDir dir;
  EXPECT_THROW(writeAtomically(dir.file("x.png"),
                               [](const std::string& temp) {
                                 test::writeBytes(temp, "half");
                                 throw std::runtime_error("codec failed");  // a library's own exception
                               }),
               OutputError);
  EXPECT_TRUE(listing(dir.path()).empty());
}
