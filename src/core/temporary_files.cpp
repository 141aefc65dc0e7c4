#include "texsynth/core/temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>

#include "texsynth/core/error.h"

namespace texsynth {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMarker = ".texsynth-tmp-";

// Eight hex digits naming this host, so a directory shared between machines never loses another
// machine's live temporaries to a PID that happens to be free here.
const std::string& hostTag() {
  static const std::string tag = [] {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) std::strcpy(name, "unknown");
    std::uint32_t hash = 2166136261u;  // FNV-1a
    for (const char* c = name; *c; ++c) hash = (hash ^ std::uint8_t(*c)) * 16777619u;
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", hash);
    return std::string(hex);
  }();
  return tag;
}

// The registry a signal handler reads: fixed storage, lock-free, no allocation.
constexpr int kSlots = 256;
constexpr std::size_t kPathBytes = 4096;
enum SlotState : int { kFree = 0, kBusy = 1, kReady = 2 };
struct Slot {
  std::atomic<int> state{kFree};
  char path[kPathBytes];
};
std::array<Slot, kSlots> slots;

extern "C" void removeTemporariesAndDie(int signal) {
  for (Slot& slot : slots)
    if (slot.state.load() == kReady) ::unlink(slot.path);
  ::signal(signal, SIG_DFL);
  ::raise(signal);  // delivered on return: the process dies of the signal, as without us
}

// Parses "HOST-PID-N" after the marker; false if it isn't one of ours.
bool parseTemporaryName(std::string_view name, std::string_view& host, long& pid) {
  if (name.empty() || name[0] != '.') return false;
  const std::size_t at = name.find(kMarker);
  if (at == std::string_view::npos) return false;
  std::string_view rest = name.substr(at + kMarker.size());
  if (rest.size() < 9 || rest[8] != '-') return false;
  host = rest.substr(0, 8);
  rest.remove_prefix(9);
  auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
  return ec == std::errc() && end < rest.data() + rest.size() && *end == '-' && pid > 0;
}

}  // namespace

std::string temporaryPathFor(const std::string& target) {
  static std::atomic<unsigned> counter{0};
  const fs::path path(target);
  // Built piecewise: GCC 12 warns falsely (-Wrestrict) on a chain of operator+ starting at a literal.
  std::string name = ".";
  name.append(path.stem().string()).append(kMarker).append(hostTag()).append("-");
  name.append(std::to_string(::getpid())).append("-").append(std::to_string(counter++));
  name.append(path.extension().string());
  return (path.has_parent_path() ? path.parent_path() / name : fs::path(name)).string();
}

bool isTemporaryName(const std::string& fileName) {
  std::string_view host;
  long pid = 0;
  return parseTemporaryName(fileName, host, pid);
}

void registerTemporary(const std::string& path) {
  if (path.size() >= kPathBytes) return;  // the next run's stale sweep removes it if it outlives us
  for (Slot& slot : slots) {
    int expected = kFree;
    if (!slot.state.compare_exchange_strong(expected, kBusy)) continue;
    std::memcpy(slot.path, path.c_str(), path.size() + 1);
    slot.state.store(kReady);
    return;
  }
}

void unregisterTemporary(const std::string& path) {
  for (Slot& slot : slots) {
    int expected = kReady;
    if (slot.state.load() != kReady || path != slot.path) continue;
    if (slot.state.compare_exchange_strong(expected, kBusy)) slot.state.store(kFree);
    return;
  }
}

void removeTemporariesOnSignals() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
      struct sigaction current {};
      ::sigaction(signal, nullptr, &current);
      if (current.sa_handler == SIG_IGN) continue;  // e.g. nohup: keep ignoring it
      struct sigaction action {};
      action.sa_handler = removeTemporariesAndDie;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal, &action, nullptr);
    }
    ::signal(SIGXFSZ, SIG_IGN);
  });
}

int removeStaleTemporaries(const std::string& directory) {
  static std::mutex mutex;
  static std::set<std::string> swept;
  std::error_code ec;
  const std::string key = fs::weakly_canonical(directory.empty() ? "." : directory, ec).string();
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (!swept.insert(key).second) return 0;
  }
  int removed = 0;
  for (fs::directory_iterator it(directory.empty() ? "." : directory, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::string_view host;
    long pid = 0;
    if (!parseTemporaryName(name, host, pid) || host != hostTag() || pid == ::getpid()) continue;
    if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    std::error_code removeError;
    if (it->is_regular_file(removeError) && fs::remove(it->path(), removeError)) ++removed;
  }
  return removed;
}

ScratchDirectory::ScratchDirectory(const std::string& forOutput) {
  std::error_code ec;
  fs::path base = fs::temp_directory_path(ec);
  if (ec) base = "/tmp";
  std::string pattern = (base / "texsynth-scratch-XXXXXX").string();
  if (!::mkdtemp(pattern.data()))
    throw OutputError(forOutput,
                      "cannot create a scratch directory in '" + base.string() + "': " + std::strerror(errno));
  path_ = pattern;
}

ScratchDirectory::~ScratchDirectory() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

}  // namespace texsynth
