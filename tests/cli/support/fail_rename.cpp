// A test shim, loaded with LD_PRELOAD into the texsynth binary: rename() into the file named by
// $TEXSYNTH_TEST_FAIL_RENAME fails with EIO, so a test can make a run's final commit fail at a
// known file, deterministically, without any hook in texsynth itself.
#include <dlfcn.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

extern "C" int rename(const char* from, const char* to) {
  const char* failing = std::getenv("TEXSYNTH_TEST_FAIL_RENAME");
  if (failing && *failing) {
    const char* name = std::strrchr(to, '/');
    if (std::strcmp(name ? name + 1 : to, failing) == 0) {
      errno = EIO;
      return -1;
    }
  }
  using Rename = int (*)(const char*, const char*);
  static const auto real = reinterpret_cast<Rename>(dlsym(RTLD_NEXT, "rename"));
  return real(from, to);
}
