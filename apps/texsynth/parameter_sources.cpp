#include "parameter_sources.h"

namespace texsynth::cli {

ParameterSource fromFile(const std::string& path) {
  return {{}, [&path] { return path; }};
}

ParameterSource fromFiles(const std::vector<std::string>& paths) {
  return {{}, [&paths] {
            std::string names;
            for (const std::string& path : paths) names += (names.empty() ? "" : ", ") + path;
            return names;
          }};
}

}  // namespace texsynth::cli
