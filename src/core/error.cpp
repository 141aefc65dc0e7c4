#include "texsynth/core/error.h"

namespace texsynth {

void failCheck(const char* condition, const char* file, int line, const std::string& message) {
  std::string text = std::string("internal check failed: ") + condition + " at " + file + ":" + std::to_string(line);
  if (!message.empty()) text += " (" + message + ")";
  throw InternalError(text);
}

}  // namespace texsynth
