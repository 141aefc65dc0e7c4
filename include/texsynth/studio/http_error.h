#pragma once
// An error the studio's API answers with its own HTTP status (404 unknown id, 413 too large, ...);
// the library's InputError and ParameterError answer 400, anything else 500.
#include <stdexcept>
#include <string>

namespace texsynth::studio {

class HttpError : public std::runtime_error {
 public:
  HttpError(int status, const std::string& message) : std::runtime_error(message), status_(status) {}
  int status() const { return status_; }

 private:
  int status_;
};

inline HttpError notFound(const std::string& what) {
  return HttpError(404, what + ": no such id");
}

}  // namespace texsynth::studio
