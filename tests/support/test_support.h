#pragma once
// Helpers shared by the test executables.
#include <functional>
#include <optional>
#include <string>

#include "texsynth/core/image.h"

namespace texsynth::test {

// A fresh empty directory under the system temp dir, removed when the object dies.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

// Writes raw bytes to a file (for crafting malformed inputs).
void writeBytes(const std::string& path, const std::string& bytes);

// Expects `read` to throw an InputError naming `path` whose message contains `problem`;
// any other outcome (no error, another exception type) is a test failure.
void expectInputError(const std::function<void()>& read, const std::string& path, const std::string& problem = "");

// Expects `run` to throw a ParameterError naming `parameter`.
void expectParameterError(const std::function<void()>& run, const std::string& parameter);

// The raw answer to an HTTP `request` sent to 127.0.0.1:`port` over a fresh connection, read until
// the server closes it ("" if nothing answers).
std::string loopbackExchange(int port, const std::string& request);

// A small deterministic RGB test pattern with structure at several scales.
Image makeTestPattern(int width, int height, unsigned seed = 1);

}  // namespace texsynth::test

// Skips the current test when optional real data (a Debian package) is absent.
#define TS_REQUIRE_DATA(optionalPath) \
  if (!(optionalPath)) GTEST_SKIP() << "real test data not installed: run scripts/install-deps.sh"
