#pragma once
// Errors at the library's boundary. Each carries *what* was wrong and *where*
// (a file, a parameter), so the CLI can print one clear line and exit non-zero.
#include <stdexcept>
#include <string>

namespace texsynth {

// Base of every error texsynth throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input data: a missing, truncated, malformed or absurd file. CLI exit code 1.
class InputError : public Error {
 public:
  InputError(const std::string& file, const std::string& problem)
      : Error(file + ": " + problem), file_(file), problem_(problem) {}
  const std::string& file() const { return file_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, problem_;
};

// A nonsense parameter value (negative size, unknown method ...). CLI exit code 2.
class ParameterError : public Error {
 public:
  ParameterError(const std::string& parameter, const std::string& problem)
      : Error(parameter + ": " + problem), parameter_(parameter), problem_(problem) {}
  const std::string& parameter() const { return parameter_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string parameter_, problem_;
};

// Writing an output failed (disk full, directory missing ...). CLI exit code 1.
class OutputError : public Error {
 public:
  OutputError(const std::string& file, const std::string& problem) : Error(file + ": " + problem) {}
};

// The user pressed cancel through a Progress; not a failure of the input.
class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled") {}
};

// A broken internal invariant: a bug in texsynth, never the user's fault.
class InternalError : public Error {
 public:
  using Error::Error;
};

[[noreturn]] void failCheck(const char* condition, const char* file, int line, const std::string& message);

}  // namespace texsynth

// Internal invariants. Not for validating user input: throw InputError/ParameterError there.
#define TS_CHECK(cond)                                                 \
  do {                                                                 \
    if (!(cond)) ::texsynth::failCheck(#cond, __FILE__, __LINE__, {}); \
  } while (0)
#define TS_CHECK_MSG(cond, msg)                                         \
  do {                                                                  \
    if (!(cond)) ::texsynth::failCheck(#cond, __FILE__, __LINE__, msg); \
  } while (0)
