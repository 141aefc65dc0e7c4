#include "texsynth/core/error.h"

namespace texsynth {

void failCheck(const char* condition, const char* file, int line, const std::string& message) {
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on a chain of operator+ here.
  std::string text = "internal check failed: ";
  text.append(condition).append(" at ").append(file).append(":").append(std::to_string(line));
  if (!message.empty()) text += " (" + message + ")";
  throw InternalError(text);
}

}  // namespace texsynth
