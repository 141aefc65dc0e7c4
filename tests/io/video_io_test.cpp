// Video I/O: mp4, webm and GIF encodes through ffmpeg (file signatures, frame counts with
// ffprobe), failed encodes that leave nothing behind, and the checks made before any work.
#include "texsynth/io/video_io.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/io/image_io.h"

namespace texsynth {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

std::optional<std::string> findProgram(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
    std::error_code ec;
    if (end > start && fs::is_regular_file(candidate, ec)) return candidate.string();
    start = end + 1;
  }
  return std::nullopt;
}

#define TS_REQUIRE_FFMPEG() \
  if (!findProgram("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed: run scripts/install-deps.sh"

// `count` PNG frames of an odd size (mp4 pads it to even sides), their names with spaces and
// quotes (ffmpeg gets them without any quoting).
std::vector<std::string> writeFrames(const TempDir& dir, int count, int width = 33, int height = 21) {
  std::vector<std::string> paths;
  for (int i = 0; i < count; ++i) {
    std::string path = dir.file("it's frame " + std::to_string(i) + ".png");
    writeImage(path, test::makeTestPattern(width, height, unsigned(i + 1)));
    paths.push_back(path);
  }
  return paths;
}

std::string fileStart(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string start(bytes, '\0');
  in.read(start.data(), std::streamsize(bytes));
  start.resize(std::size_t(in.gcount()));
  return start;
}

// The number of video frames ffprobe counts in `path`, or -1 if ffprobe is not installed.
int probedFrameCount(const std::string& path) {
  if (!findProgram("ffprobe")) return -1;
  std::string command =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 '" + path +
      "'";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buffer[64] = {};
  std::string output;
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  ::pclose(pipe);
  return std::atoi(output.c_str());
}

// Only `expected` in `dir`: no temporaries left beside the outputs.
void expectOnlyFiles(const std::string& dir, std::size_t expected) {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().string().find("texsynth-tmp"), std::string::npos) << entry.path();
    ++count;
  }
  EXPECT_EQ(count, expected);
}

TEST(VideoIo, EncodesMp4WebmAndGifWithEveryFrame) {
  TS_REQUIRE_FFMPEG();
  TempDir dir;
  const std::vector<std::string> frames = writeFrames(dir, 6);
  struct Case {
    std::string name;
    std::size_t offset;
    std::string signature;
  };
  const std::vector<Case> cases = {
      {"out.mp4", 4, "ftyp"}, {"out.webm", 0, std::string("\x1A\x45\xDF\xA3", 4)}, {"out.GIF", 0, "GIF89a"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.file(c.name);
    encodeVideo(frames, 12.5, path);
    ASSERT_TRUE(fs::is_regular_file(path));
    EXPECT_GT(fs::file_size(path), 0u);
    EXPECT_EQ(fileStart(path, c.offset + c.signature.size()).substr(c.offset), c.signature);
    int probed = probedFrameCount(path);
    if (probed >= 0) {
      EXPECT_EQ(probed, 6);
    }
  }
  expectOnlyFiles(dir.path(), frames.size() + cases.size());
}

TEST(VideoIo, MissingFrameFailsWithoutTouchingTheTarget) {
  TS_REQUIRE_FFMPEG();
  TempDir dir;
  std::vector<std::string> frames = writeFrames(dir, 3);
  const std::string path = dir.file("anim.mp4");
  std::vector<std::string> missing = frames;
  missing[1] = dir.file("nowhere.png");
  EXPECT_THROW(encodeVideo(missing, 24, path), OutputError);
  EXPECT_FALSE(fs::exists(path));

  encodeVideo(frames, 24, path);
  const std::string good = readFileBytes(path);
  try {
    encodeVideo(missing, 24, path);
    ADD_FAILURE() << "encoded a missing frame";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("nowhere.png"), std::string::npos) << e.what();
  }
  EXPECT_EQ(readFileBytes(path), good);
  expectOnlyFiles(dir.path(), frames.size() + 1);
}

TEST(VideoIo, FrameFfmpegCannotDecodeFailsWithItsErrorLine) {
  TS_REQUIRE_FFMPEG();
  TempDir dir;
  std::vector<std::string> frames = writeFrames(dir, 4);
  for (const std::string name : {"clip.mp4", "clip.webm", "clip.gif"}) {
    SCOPED_TRACE(name);
    const std::string path = dir.file(name);
    encodeVideo(frames, 10, path);
    const std::string good = readFileBytes(path);
    std::vector<std::string> broken = frames;
    broken[2] = dir.file("broken.png");
    test::writeBytes(broken[2], "not a png at all");
    try {
      encodeVideo(broken, 10, path);
      ADD_FAILURE() << "encoded a broken frame";
    } catch (const OutputError& e) {
      std::string message = e.what();
      EXPECT_EQ(message.rfind(path + ": cannot encode the video: ffmpeg failed", 0), 0u) << message;
      EXPECT_EQ(message.find("texsynth-tmp"), std::string::npos) << message;
      EXPECT_EQ(message.find(" @ 0x"), std::string::npos) << message;
    }
    EXPECT_EQ(readFileBytes(path), good);
    fs::remove(broken[2]);
  }
  expectOnlyFiles(dir.path(), frames.size() + 3);
}

TEST(VideoIo, NoFramesOrBadRateFailBeforeWriting) {
  TS_REQUIRE_FFMPEG();
  TempDir dir;
  std::vector<std::string> frames = writeFrames(dir, 2);
  EXPECT_THROW(encodeVideo({}, 24, dir.file("a.mp4")), OutputError);
  test::expectParameterError([&] { encodeVideo(frames, 0, dir.file("a.mp4")); }, "fps");
  test::expectParameterError([&] { encodeVideo(frames, -3, dir.file("a.mp4")); }, "fps");
  EXPECT_THROW(encodeVideo(frames, 24, dir.file("no such dir/a.mp4")), OutputError);
  expectOnlyFiles(dir.path(), frames.size());
}

TEST(VideoIo, RecognisesVideoExtensions) {
  EXPECT_TRUE(isVideoFile("a.mp4"));
  EXPECT_TRUE(isVideoFile("dir/b.WEBM"));
  EXPECT_TRUE(isVideoFile("/x/y/c.Gif"));
  EXPECT_FALSE(isVideoFile("a.png"));
  EXPECT_FALSE(isVideoFile("a.avi"));
  EXPECT_FALSE(isVideoFile("mp4"));
  EXPECT_FALSE(isVideoFile("dir.mp4/frame"));
  EXPECT_FALSE(isVideoFile(""));
}

TEST(VideoIo, RequireVideoEncoderRejectsOtherExtensions) {
  for (const std::string path : {"x.avi", "x.png", "x"}) {
    try {
      requireVideoEncoder(path);
      ADD_FAILURE() << "accepted " << path;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.parameter(), "output");
      EXPECT_NE(std::string(e.what()).find("'" + path + "': texsynth writes videos as .mp4, .webm or .gif"),
                std::string::npos)
          << e.what();
    }
  }
  TempDir dir;
  EXPECT_THROW(encodeVideo(writeFrames(dir, 1), 24, dir.file("x.avi")), ParameterError);
  EXPECT_FALSE(fs::exists(dir.file("x.avi")));
}

TEST(VideoIo, MissingFfmpegIsAClearOutputError) {
  TempDir empty;
  const char* saved = std::getenv("PATH");
  const std::string oldPath = saved ? saved : "";
  ::setenv("PATH", empty.path().c_str(), 1);
  std::optional<std::string> message;
  try {
    requireVideoEncoder("anim.mp4");
  } catch (const OutputError& e) {
    message = e.what();
  }
  if (saved)
    ::setenv("PATH", oldPath.c_str(), 1);
  else
    ::unsetenv("PATH");
  ASSERT_TRUE(message) << "no error without ffmpeg on PATH";
  EXPECT_EQ(*message,
            "anim.mp4: needs the ffmpeg program to encode videos; install it (apt-get install ffmpeg) or write PNG "
            "frames only");
  if (findProgram("ffmpeg")) {
    EXPECT_NO_THROW(requireVideoEncoder("anim.webm"));
  }
}

}  // namespace
}  // namespace texsynth
