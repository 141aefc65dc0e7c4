#include "texsynth/io/readable_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "texsynth/core/error.h"

namespace texsynth {
namespace fs = std::filesystem;

void requireReadableFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) throw InputError(path, "file does not exist");
  if (ec) throw InputError(path, "cannot be accessed: " + ec.message());
  if (fs::is_directory(status)) throw InputError(path, "is a directory, not a file");
  if (!fs::is_regular_file(status)) throw InputError(path, "is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot be read: ") + std::strerror(errno));
}

}  // namespace texsynth
