// Where `texsynth` keeps its cache: $TEXSYNTH_CACHE, else $XDG_CACHE_HOME/texsynth (when
// absolute), else $HOME/.cache/texsynth. Empty variables count as unset.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_runner.h"
#include "texsynth/io/image_io.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;
namespace fs = std::filesystem;

namespace {

// Analysis cache files (exemplar-*.tsxa) directly in `directory`.
int analysisFiles(const std::string& directory) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return 0;
  int count = 0;
  for (const auto& entry : fs::directory_iterator(directory))
    count += entry.path().extension() == ".tsxa" && entry.path().filename().string().starts_with("exemplar-");
  return count;
}

// A parallel synthesis, which analyses (and caches) the exemplar; `environment` chooses the cache.
RunResult synthesize(const test::TempDir& dir, const std::string& environment) {
  const std::string exemplar = dir.file("exemplar.png");
  if (!fs::exists(exemplar)) writeImage(exemplar, test::makeTestPattern(48, 40));
  return runTexsynth(
      "image " + exemplar + " --method parallel --size 24 --tileable never --quiet -o " + dir.file("out.png"), dir,
      environment);
}

}  // namespace

TEST(CacheCli, XdgCacheHomeHoldsTheCacheWhenTexsynthCacheIsEmpty) {
  test::TempDir dir;
  // runTexsynth sets TEXSYNTH_CACHE; an empty value here overrides it and counts as unset.
  RunResult r = synthesize(dir, "TEXSYNTH_CACHE= XDG_CACHE_HOME=" + dir.file("xdg") + " HOME=" + dir.file("home"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(analysisFiles(dir.file("xdg/texsynth")), 1);
  EXPECT_FALSE(fs::exists(dir.file("home/.cache")));
}

TEST(CacheCli, TexsynthCacheOverridesXdgCacheHome) {
  test::TempDir dir;
  RunResult r = synthesize(
      dir, "TEXSYNTH_CACHE=" + dir.file("mine") + " XDG_CACHE_HOME=" + dir.file("xdg") + " HOME=" + dir.file("home"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(analysisFiles(dir.file("mine")), 1);
  EXPECT_FALSE(fs::exists(dir.file("xdg")));
  EXPECT_FALSE(fs::exists(dir.file("home/.cache")));
}

TEST(CacheCli, RelativeOrEmptyXdgCacheHomeFallsBackToHome) {
  test::TempDir dir;
  for (const char* value : {"texsynth-relative-xdg-cache-test", ""}) {
    const std::string xdg = value;
    SCOPED_TRACE("XDG_CACHE_HOME='" + xdg + "'");
    fs::remove_all(dir.file("home"));
    RunResult r = synthesize(dir, "TEXSYNTH_CACHE= XDG_CACHE_HOME=" + xdg + " HOME=" + dir.file("home"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(analysisFiles(dir.file("home/.cache/texsynth")), 1);
  }
  EXPECT_FALSE(fs::exists("texsynth-relative-xdg-cache-test"));  // the test's working directory
}

TEST(CacheCli, HelpNamesTheCacheDirectory) {
  test::TempDir dir;
  RunResult r = runTexsynth("--help", dir, "TEXSYNTH_CACHE=" + dir.file("shown"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find(dir.file("shown")), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("XDG_CACHE_HOME"), std::string::npos) << r.out;
}
