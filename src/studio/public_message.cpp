// Error messages without the server's private paths.
#include "texsynth/studio/public_message.h"

#include <regex>

#include "texsynth/core/temporary_files.h"

namespace texsynth::studio {

namespace {

// What a private path stands for: a temporary's target name, or its own file name.
std::string standIn(const std::string& path) {
  const std::string name = path.substr(path.find_last_of('/') + 1);
  if (name.rfind(kScratchDirectoryPrefix, 0) == 0) return "a temporary folder";
  const std::string target = temporaryTargetName(name);
  return target.empty() ? name : target;
}

}  // namespace

std::string withoutTemporaryPaths(const std::string& message) {
  // A path runs to a space or a quote; a trailing ':' or ',' is the sentence's.
  static const std::regex kPath(R"([^\s'"]*()" + std::string(kScratchDirectoryPrefix) + R"(|\)" +
                                std::string(kTemporaryMarker) + R"()[^\s'"]*?(?=[:,;]?(\s|'|"|$)))");
  std::string out;
  auto last = message.cbegin();
  for (std::sregex_iterator it(message.begin(), message.end(), kPath), end; it != end; ++it) {
    out.append(last, message.cbegin() + it->position());
    out += standIn(it->str());
    last = message.cbegin() + it->position() + it->length();
  }
  out.append(last, message.cend());
  return out;
}

}  // namespace texsynth::studio
