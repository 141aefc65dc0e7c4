#include "texsynth/io/video_io.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/temporary_files.h"

extern char** environ;

namespace texsynth {
namespace {
namespace fs = std::filesystem;

// The ffmpeg program on PATH (an empty PATH entry is the current directory, as for execvp).
std::optional<std::string> findFfmpeg() {
  const char* pathEnv = std::getenv("PATH");
  const std::string dirs = pathEnv ? pathEnv : "/usr/local/bin:/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = dirs.substr(start, end - start);
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/ffmpeg";
    struct stat st {};
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

// The encoder's arguments for the output format (after the input, before the output file).
std::vector<std::string> formatArguments(const std::string& extension) {
  if (extension == "mp4")
    // H.264 with 4:2:0 chroma needs even sides: pad an odd width or height by one column/row.
    return {"-c:v",      "libx264",    "-pix_fmt", "yuv420p", "-crf", "18", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
            "-movflags", "+faststart", "-f",       "mp4"};
  if (extension == "webm")
    return {"-c:v", "libvpx-vp9", "-crf", "32", "-b:v", "0", "-pix_fmt", "yuv420p", "-row-mt", "1", "-f", "webm"};
  // gif: one palette for the whole animation, made from the pixels that change between frames.
  return {"-vf", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer", "-loop", "0", "-f",
          "gif"};
}

// fps as ffmpeg reads it: the shortest decimal that round-trips ("24", "12.5").
std::string formatRate(double fps) {
  std::array<char, 64> buffer{};
  auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), fps);
  return std::string(buffer.data(), result.ptr);
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

// The last line of ffmpeg's error output that says something (not "Last message repeated").
std::string lastErrorLine(const std::string& logPath) {
  std::ifstream in(logPath);
  std::string line, last;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    line.erase(0, first);
    if (line.rfind("Last message repeated", 0) == 0 || line == "Conversion failed!") continue;
    // "[png @ 0x55d0c2a4e6c0] Invalid PNG signature" -> "png: Invalid PNG signature"
    if (std::size_t at = line.find(" @ 0x"), close = line.find("] ");
        line[0] == '[' && at < close && close != std::string::npos)
      line = line.substr(1, at - 1) + ": " + line.substr(close + 2);
    last = line;
  }
  constexpr std::size_t kMaxLength = 400;
  if (last.size() > kMaxLength) last = last.substr(0, kMaxLength) + "...";
  return last;
}

// Runs `program` with `args` (no shell): stdin and stdout on /dev/null, stderr into `logPath`.
// Returns a description of the failure, or "" if it exited with status 0.
std::string runProgram(const std::string& program, const std::vector<std::string>& args, const std::string& logPath) {
  std::vector<char*> argv;
  argv.reserve(args.size() + 2);
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  if (int err = posix_spawn_file_actions_init(&actions); err != 0)
    return std::string("cannot start ffmpeg: ") + std::strerror(err);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = 0;
  const int spawnError = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawnError != 0) return "cannot run '" + program + "': " + std::strerror(spawnError);
  registerChildProcess(pid);  // a signal that ends us ends the encoder too

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      unregisterChildProcess(pid);
      return std::string("cannot wait for ffmpeg: ") + std::strerror(errno);
    }
  }
  unregisterChildProcess(pid);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  if (WIFSIGNALED(status)) return "ffmpeg was killed by signal " + std::to_string(WTERMSIG(status));
  return "ffmpeg failed with exit status " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

bool isVideoFile(const std::string& path) {
  const std::string extension = fileExtension(path);
  return extension == "mp4" || extension == "webm" || extension == "gif";
}

void requireVideoEncoder(const std::string& path) {
  if (!isVideoFile(path))
    throw ParameterError("output", "'" + path + "': texsynth writes videos as .mp4, .webm or .gif");
  if (!findFfmpeg())
    throw OutputError(path,
                      "needs the ffmpeg program to encode videos; install it (apt-get install ffmpeg) or write PNG "
                      "frames only");
}

void encodeVideo(const std::vector<std::string>& framePaths, double fps, const std::string& path) {
  requireVideoEncoder(path);
  if (!(std::isfinite(fps) && fps > 0))
    throw ParameterError("fps", "must be a positive number of frames per second, not " + formatRate(fps));
  if (framePaths.empty()) throw OutputError(path, "no frames to encode");
  const std::string ffmpeg = *findFfmpeg();

  // ffmpeg reads a numbered sequence: link the frames, whatever their names, into a private
  // directory as frame_000000.png, frame_000001.png ... (no escaping of names needed).
  ScratchDirectory scratch(path);
  for (std::size_t i = 0; i < framePaths.size(); ++i) {
    std::error_code ec;
    if (!fs::is_regular_file(framePaths[i], ec))
      throw OutputError(path, "frame '" + framePaths[i] + "' does not exist or is not a file");
    const fs::path source = fs::absolute(framePaths[i], ec);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06zu.png", i);
    fs::create_symlink(source, fs::path(scratch.path()) / name, ec);
    if (ec) throw OutputError(path, "cannot link frame '" + framePaths[i] + "' for ffmpeg: " + ec.message());
  }
  const std::string logPath = scratch.path() + "/ffmpeg.log";
  const std::string extension = fileExtension(path);

  writeAtomically(path, [&](const std::string& tempPath) {
    // -xerror: a frame that does not decode fails the encode instead of being skipped.
    std::vector<std::string> args = {
        "-hide_banner", "-loglevel",  "error",         "-nostdin", "-y",
        "-xerror",      "-framerate", formatRate(fps), "-i",       scratch.path() + "/frame_%06d.png"};
    for (std::string& arg : formatArguments(extension)) args.push_back(std::move(arg));
    // The format is given explicitly (-f above), so the temporary's name does not matter.
    args.insert(args.end(), {"-threads", std::to_string(threadLimit()), tempPath});

    std::string failure = runProgram(ffmpeg, args, logPath);
    std::error_code ec;
    if (failure.empty() && !(fs::is_regular_file(tempPath, ec) && fs::file_size(tempPath, ec) > 0))
      failure = "ffmpeg wrote no video";
    if (failure.empty()) return;
    std::string detail = lastErrorLine(logPath);
    replaceAll(detail, tempPath, path);
    replaceAll(detail, scratch.path() + "/", "");
    throw OutputError(path, "cannot encode the video: " + (detail.empty() ? failure : failure + ": " + detail));
  });
}

}  // namespace texsynth
