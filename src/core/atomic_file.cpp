#include "texsynth/core/atomic_file.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "texsynth/core/error.h"

namespace texsynth {
namespace fs = std::filesystem;

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  fs::path target(path);
  fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw OutputError(path, "directory '" + dir.string() + "' does not exist");
  if (fs::is_directory(target, ec)) throw OutputError(path, "is a directory");
  // Keep the real extension last: some writers pick the format from it.
  // Built piecewise: GCC 12 warns falsely (-Wrestrict) on a chain of operator+ starting at a literal.
  std::string name = ".";
  name.append(target.stem().string()).append(".tmp").append(std::to_string(::getpid()));
  name.append(target.extension().string());
  std::string temp = (dir / name).string();
  try {
    write(temp);
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
  if (!fs::exists(temp, ec)) throw OutputError(path, "writer produced no file");
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw OutputError(path, "cannot move the finished file into place: " + ec.message());
  }
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  writeAtomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw OutputError(path, std::string("cannot open for writing: ") + std::strerror(errno));
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out) throw OutputError(path, "write failed (disk full?)");
  });
}

std::string readFileBytes(const std::string& path, std::size_t maxBytes) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "file does not exist");
  if (fs::is_directory(path, ec)) throw InputError(path, "is a directory, not a file");
  auto size = fs::file_size(path, ec);
  if (ec) throw InputError(path, "cannot read size: " + ec.message());
  if (size > maxBytes) throw InputError(path, "file is too large (" + std::to_string(size) + " bytes)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
  std::string bytes(size, '\0');
  in.read(bytes.data(), std::streamsize(size));
  if (std::size_t(in.gcount()) != size) throw InputError(path, "read failed");
  return bytes;
}

std::string fileExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace texsynth
