// `texsynth studio` as a service manager runs it: it refuses a bad start with one line, and a
// termination signal stops it cleanly, after which it dies of that signal (as the other commands do).
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "cli_runner.h"
#include "test_support.h"

using namespace texsynth;

namespace {

// One line from `fd`, waiting up to `timeout`; empty if none came.
std::string readLine(int fd, std::chrono::milliseconds timeout) {
  std::string line;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  char c;
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd ready{fd, POLLIN, 0};
    if (::poll(&ready, 1, 100) <= 0) continue;
    if (::read(fd, &c, 1) != 1) break;
    if (c == '\n') return line;
    line += c;
  }
  return line;
}

// The status line of GET `path` on the loopback port.
std::string statusLine(int port, const std::string& path) {
  const std::string answer =
      test::loopbackExchange(port, "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
  return answer.substr(0, answer.find("\r\n"));
}

// waitpid for up to `timeout`; the status, or nothing if the process still runs.
std::optional<int> waitFor(pid_t pid, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return std::nullopt;
}

TEST(StudioCli, SigtermStopsTheStudioWhichThenDiesOfIt) {
  test::TempDir dir;
  int output[2];
  ASSERT_EQ(::pipe(output), 0);
  const std::string cache = "TEXSYNTH_CACHE=" + dir.file("cache");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {  // the studio on any free port, printing it as JSON
    ::dup2(output[1], STDOUT_FILENO);
    ::close(output[0]);
    ::putenv(const_cast<char*>(cache.c_str()));
    ::execl(TEXSYNTH_BINARY, "texsynth", "studio", "--port", "0", "--json", "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(output[1]);
  const std::string started = readLine(output[0], std::chrono::seconds(30));
  ::close(output[0]);
  int port = 0;
  try {
    port = nlohmann::json::parse(started).at("port").get<int>();
  } catch (const std::exception&) {
    ADD_FAILURE() << "no port printed: '" << started << "'";
  }
  if (port > 0) {
    EXPECT_EQ(statusLine(port, "/api/health"), "HTTP/1.1 200 OK");
  }
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  const std::optional<int> status = waitFor(pid, std::chrono::seconds(30));
  if (!status) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    FAIL() << "the studio did not stop on SIGTERM";
  }
  EXPECT_TRUE(WIFSIGNALED(*status) && WTERMSIG(*status) == SIGTERM)
      << (WIFEXITED(*status) ? "exited with " + std::to_string(WEXITSTATUS(*status)) : "died of another signal");
}

TEST(StudioCli, AMissingPageFolderIsRefusedAtStart) {
  test::TempDir dir;
  // `timeout`: a studio that starts anyway would serve until killed.
  const test::RunResult r = test::runTexsynth("studio --port 0 --web-root " + dir.file("no-web"), dir, "timeout 20");
  test::expectOneLineError(r, 1, dir.file("no-web"));
}

}  // namespace
