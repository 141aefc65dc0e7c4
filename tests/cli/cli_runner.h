#pragma once
// Runs the texsynth binary the way a user would, capturing exit code, stdout and stderr.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"

namespace texsynth::test {

struct RunResult {
  int exitCode = -1;
  std::string out, err;
};

// Runs the binary with a private analysis cache; `environment` is prepended (e.g. "TEXSYNTH_DATA=/x").
inline RunResult runTexsynth(const std::string& arguments, const test::TempDir& dir,
                             const std::string& environment = "") {
  std::string outFile = dir.file("stdout.txt"), errFile = dir.file("stderr.txt");
  std::string command = "TEXSYNTH_CACHE=" + dir.file("cache") + " " + environment + " " + std::string(TEXSYNTH_BINARY) +
                        " " + arguments + " >" + outFile + " 2>" + errFile + " </dev/null";
  int status = std::system(command.c_str());
  RunResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFileBytes(outFile);
  r.err = readFileBytes(errFile);
  return r;
}

inline int lineCount(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

// The run failed with `exitCode` and one stderr line that mentions `mention`.
inline void expectOneLineError(const RunResult& r, int exitCode, const std::string& mention) {
  EXPECT_EQ(r.exitCode, exitCode) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
}

}  // namespace texsynth::test
