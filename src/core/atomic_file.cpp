#include "texsynth/core/atomic_file.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "texsynth/core/error.h"
#include "texsynth/core/output_batch.h"
#include "texsynth/core/temporary_files.h"

namespace texsynth {
namespace fs = std::filesystem;

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write, Staging staging) {
  checkWritableDestination(path);
  const fs::path target(path);
  removeStaleTemporaries(target.has_parent_path() ? target.parent_path().string() : ".");
  const std::string temp = temporaryPathFor(path);
  registerTemporary(temp);
  const auto discard = [&temp] {
    std::error_code ec;
    fs::remove(temp, ec);
    unregisterTemporary(temp);
  };
  try {
    write(temp);
  } catch (const Error&) {
    discard();
    throw;
  } catch (const std::bad_alloc&) {
    discard();
    throw;
  } catch (const std::exception& e) {  // a library's own exception (OpenEXR, stb): say which file
    discard();
    throw OutputError(path, std::string("cannot write: ") + e.what());
  }
  std::error_code ec;
  if (!fs::exists(temp, ec)) {
    unregisterTemporary(temp);
    throw OutputError(path, "writer produced no file");
  }
  if (OutputBatch* batch = OutputBatch::active(); batch && staging == Staging::WithRun) {
    batch->stage(temp, path);
    return;
  }
  fs::rename(temp, target, ec);
  if (ec) {
    discard();
    throw OutputError(path, "cannot move the finished file into place: " + ec.message());
  }
  unregisterTemporary(temp);
}

void checkWritableDestination(const std::string& path) {
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw OutputError(path, "directory '" + dir.string() + "' does not exist");
  if (fs::is_directory(target, ec)) throw OutputError(path, "is a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw OutputError(path, "cannot write in directory '" + dir.string() + "': " + std::strerror(errno));
  if (fs::exists(target, ec) && !fs::is_regular_file(target, ec))
    throw OutputError(path, "exists and is not a regular file");
}

void writeFileAtomically(const std::string& path, const std::string& bytes, Staging staging) {
  writeAtomically(
      path,
      [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary);
        if (!out) throw OutputError(path, std::string("cannot open for writing: ") + std::strerror(errno));
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.flush();
        if (!out) throw OutputError(path, std::string("write failed: ") + std::strerror(errno));
        out.close();
        if (!out) throw OutputError(path, std::string("write failed: ") + std::strerror(errno));
      },
      staging);
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
