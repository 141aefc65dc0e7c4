// encodeVdb and decodeVdb through the OpenVDB module (vdb/vdb_module.h), loaded on first use:
// from $TEXSYNTH_VDB_MODULE when set, else next to the program (../lib/, as the build lays it
// out), else from the build tree the program was built in.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "texsynth/core/error.h"
#include "vdb/vdb_module.h"
#include "volume_codecs.h"

#ifndef TEXSYNTH_VDB_MODULE
#define TEXSYNTH_VDB_MODULE "libtexsynth_vdb.so"
#endif

namespace texsynth::volume_codec {
namespace {
namespace fs = std::filesystem;

constexpr const char* kModuleName = "libtexsynth_vdb.so";

// The places to look, in order.
std::vector<std::string> modulePaths() {
  if (const char* env = std::getenv("TEXSYNTH_VDB_MODULE"); env && *env) return {env};
  std::vector<std::string> paths;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (!error) paths.push_back((program.parent_path().parent_path() / "lib" / kModuleName).string());
  paths.push_back(TEXSYNTH_VDB_MODULE);
  return paths;
}

// The module's codec, loaded once; throws `fail(reason)` when it cannot be loaded.
template <class Fail>
const vdb_module::Codec& codec(Fail&& fail) {
  static std::once_flag once;
  static const vdb_module::Codec* loaded = nullptr;
  static std::string problem;
  std::call_once(once, [] {
    std::string tried;
    for (const std::string& path : modulePaths()) {
      // Kept loaded for the life of the process (OpenVDB registers its types once).
      if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
        if (auto entry = reinterpret_cast<vdb_module::EntryPoint>(dlsym(handle, vdb_module::kEntryPoint))) {
          loaded = entry();
          return;
        }
      }
      const char* why = dlerror();
      tried += (tried.empty() ? "" : "; ") + (why ? std::string(why) : path);
    }
    problem = "OpenVDB support is missing (set TEXSYNTH_VDB_MODULE to " + std::string(kModuleName) + "): " + tried;
  });
  if (!loaded) fail(problem);
  return *loaded;
}

}  // namespace

std::string encodeVdb(const std::string& path, const Volume& volume) {
  const vdb_module::Codec& vdb = codec([&](const std::string& why) { throw OutputError(path, why); });
  return vdb.encode(path, volume.nx, volume.ny, volume.nz, volume.channels, volume.voxels.data());
}

Volume decodeVdb(const std::string& path, std::string bytes) {
  const vdb_module::Codec& vdb = codec([&](const std::string& why) { throw InputError(path, why); });
  vdb_module::DenseVolume dense = vdb.decode(path, std::move(bytes));
  Volume volume(dense.nx, dense.ny, dense.nz, dense.channels);
  volume.voxels = std::move(dense.voxels);
  return volume;
}

}  // namespace texsynth::volume_codec
