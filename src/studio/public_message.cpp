// Error messages without the server's private paths.
#include "texsynth/studio/public_message.h"

#include <regex>

namespace texsynth::studio {

namespace {

constexpr const char* kScratch = "texsynth-scratch-";  // ScratchDirectory's folders
constexpr const char* kTemporary = ".texsynth-tmp-";   // atomic writes' temporaries (temporary_files.h)

// What a private path stands for: its file name, without a temporary's marking.
std::string standIn(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  if (name.rfind(kScratch, 0) == 0) return "a temporary folder";
  if (const std::size_t marker = name.find(kTemporary); marker != std::string::npos) {
    // ".NAME.texsynth-tmp-HOST-PID-N.EXT" -> "NAME.EXT"
    const std::size_t extension = name.find('.', marker + 1);
    name = name.substr(name[0] == '.' ? 1 : 0, marker - (name[0] == '.' ? 1 : 0)) +
           (extension == std::string::npos ? "" : name.substr(extension));
  }
  return name;
}

}  // namespace

std::string withoutTemporaryPaths(const std::string& message) {
  // A path runs to a space or a quote; a trailing ':' or ',' is the sentence's.
  static const std::regex kPath(R"([^\s'"]*(texsynth-scratch-|\.texsynth-tmp-)[^\s'"]*?(?=[:,;]?(\s|'|"|$)))");
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
