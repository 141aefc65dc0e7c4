#include "texsynth/core/temporary_files.h"

#include <dirent.h>
#include <fcntl.h>
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
#include <unordered_set>

#include "texsynth/core/error.h"

namespace texsynth {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMarker = kTemporaryMarker;

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

// The registries a signal handler reads: fixed storage, lock-free reads, no allocation. Writers
// (ordinary code) serialize on `registryMutex`; a slot's path is complete before it turns Ready.
constexpr int kSlots = 256, kDirectorySlots = 64;
constexpr std::size_t kPathBytes = 4096;
enum SlotState : int { kFree = 0, kBusy = 1, kReady = 2 };
struct Slot {
  std::atomic<int> state{kFree};
  char path[kPathBytes] = {};  // zero: constant-initialized, so the registry costs no start-up work
};
constinit std::array<Slot, kSlots> slots;

// A directory to clean: kind 0 holds temporaries (swept for this process's), 1 and 2 are
// DirectoryCleanup's IfEmpty and WithContents. `uses` counts the temporaries or registrations
// that keep it; `order` is when it was registered (created directories go deepest, latest, first).
enum DirectoryKind : int { kHoldsTemporaries = 0, kIfEmpty = 1, kWithContents = 2 };
struct DirectorySlot : Slot {
  int kind = 0, uses = 0;
  std::atomic<unsigned> order{0};
};
constinit std::array<DirectorySlot, kDirectorySlots> directorySlots;
std::mutex registryMutex;
unsigned registrations = 0;

// "HOST-PID-": what follows the marker in this process's temporaries, filled at registration
// (again in a forked child) so the handler only compares bytes.
char ownTag[32] = {};

bool claim(Slot& slot, const std::string& path) {
  int expected = kFree;
  if (!slot.state.compare_exchange_strong(expected, kBusy)) return false;
  std::memcpy(slot.path, path.c_str(), path.size() + 1);
  slot.state.store(kReady);
  return true;
}

void release(Slot& slot) {
  int expected = kReady;
  if (slot.state.compare_exchange_strong(expected, kBusy)) slot.state.store(kFree);
}

// Under registryMutex: one more use of `directory` as `kind`, in a slot of its own if new.
void retainDirectory(const std::string& directory, int kind) {
  if (directory.size() >= kPathBytes) return;
  for (DirectorySlot& slot : directorySlots)
    if (slot.state.load() == kReady && slot.kind == kind && directory == slot.path) {
      ++slot.uses;
      return;
    }
  for (DirectorySlot& slot : directorySlots) {
    if (slot.state.load() != kFree) continue;
    slot.kind = kind, slot.uses = 1;
    slot.order.store(++registrations);
    claim(slot, directory);
    return;
  }
}

// Under registryMutex: one use fewer; the slot is freed with the last.
void releaseDirectory(const std::string& directory, int kind) {
  for (DirectorySlot& slot : directorySlots)
    if (slot.state.load() == kReady && slot.kind == kind && directory == slot.path) {
      if (--slot.uses == 0) release(slot);
      return;
    }
}

// Under registryMutex: every registered temporary, full paths of any length (what keeps a
// directory's count exact when a path is unregistered twice or never was).
std::unordered_set<std::string>& registeredTemporaries() {
  static std::unordered_set<std::string> paths;
  return paths;
}

// Absolute, so the handler finds it whatever the working directory is by then.
std::string directoryOf(const std::string& path) {
  std::error_code ec;
  const fs::path parent = fs::path(path).parent_path();
  const fs::path absolute = fs::absolute(parent.empty() ? fs::path(".") : parent, ec);
  return (ec ? parent : absolute.lexically_normal()).string();
}

// Signal-safe: removes the entries of `directory` that `remove` selects (by name), with
// getdents64 and unlinkat only. Rereads until a pass removes nothing, since unlinking while
// reading may skip entries.
template <class Select>
void removeEntries(const char* directory, const Select& remove) {
  const int fd = ::open(directory, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  alignas(8) char buffer[8192];
  for (int pass = 0; pass < 16; ++pass) {
    bool removed = false;
    ::lseek(fd, 0, SEEK_SET);
    for (ssize_t n; (n = ::getdents64(fd, buffer, sizeof buffer)) > 0;)
      for (ssize_t at = 0; at < n;) {
        const auto* entry = reinterpret_cast<const struct dirent64*>(buffer + at);
        at += entry->d_reclen;
        const char* name = entry->d_name;
        if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0 || !remove(name)) continue;
        if (::unlinkat(fd, name, 0) == 0 || ::unlinkat(fd, name, AT_REMOVEDIR) == 0) removed = true;
      }
    if (!removed) break;
  }
  ::close(fd);
}

// Signal-safe: is `name` a temporary of this process?
bool isOwnTemporary(const char* name) {
  const char* marker = name[0] == '.' ? std::strstr(name, kMarker.data()) : nullptr;
  return marker && ownTag[0] && std::strncmp(marker + kMarker.size(), ownTag, std::strlen(ownTag)) == 0;
}

// Helper processes (a video encoder) that must not outlive us, and so not write any more.
constexpr int kChildSlots = 8;
std::array<std::atomic<pid_t>, kChildSlots> children{};

// While a SignalsHeld lives, a signal is only noted here and acted on when it goes.
std::atomic<bool> holdingSignals{false};
std::atomic<int> heldSignal{0};

extern "C" void removeTemporariesAndDie(int signal) {
  if (holdingSignals.load()) {
    heldSignal.store(signal);
    return;
  }
  for (auto& child : children)
    if (const pid_t pid = child.load(); pid > 0) ::kill(pid, SIGKILL);
  for (Slot& slot : slots)
    if (slot.state.load() == kReady) ::unlink(slot.path);
  for (DirectorySlot& slot : directorySlots) {
    if (slot.state.load() != kReady) continue;
    if (slot.kind == kHoldsTemporaries) removeEntries(slot.path, isOwnTemporary);
    if (slot.kind == kWithContents) {
      removeEntries(slot.path, [](const char*) { return true; });
      ::rmdir(slot.path);
    }
  }
  // Created output directories, latest (deepest) first; rmdir leaves any that are not empty.
  for (unsigned below = ~0u;;) {
    DirectorySlot* latest = nullptr;
    for (DirectorySlot& slot : directorySlots)
      if (slot.state.load() == kReady && slot.kind == kIfEmpty && slot.order.load() < below &&
          (!latest || slot.order.load() > latest->order.load()))
        latest = &slot;
    if (!latest) break;
    ::rmdir(latest->path);
    below = latest->order.load();
  }
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

std::string temporaryTargetName(const std::string& fileName) {
  // temporaryPathFor's "." + stem + marker + "HOST-PID-N" + extension.
  const std::size_t marker = fileName.find(kMarker);
  if (marker == std::string::npos) return "";
  const std::size_t start = fileName[0] == '.' && marker > 0 ? 1 : 0;
  const std::size_t extension = fileName.find('.', marker + kMarker.size());
  return fileName.substr(start, marker - start) + (extension == std::string::npos ? "" : fileName.substr(extension));
}

void registerTemporary(const std::string& path) {
  std::lock_guard<std::mutex> lock(registryMutex);
  static long taggedPid = 0;  // a forked child names its temporaries with its own PID
  if (taggedPid != long(::getpid())) {
    taggedPid = long(::getpid());
    std::snprintf(ownTag, sizeof ownTag, "%s-%ld-", hostTag().c_str(), taggedPid);
  }
  if (!registeredTemporaries().insert(path).second) return;
  retainDirectory(directoryOf(path), kHoldsTemporaries);
  if (path.size() >= kPathBytes) return;  // its directory's sweep finds it
  for (Slot& slot : slots)
    if (claim(slot, path)) return;
}

void unregisterTemporary(const std::string& path) {
  std::lock_guard<std::mutex> lock(registryMutex);
  if (registeredTemporaries().erase(path) == 0) return;  // never registered, or already gone
  releaseDirectory(directoryOf(path), kHoldsTemporaries);
  for (Slot& slot : slots)
    if (slot.state.load() == kReady && path == slot.path) return release(slot);
}

void registerDirectory(const std::string& path, DirectoryCleanup cleanup) {
  std::lock_guard<std::mutex> lock(registryMutex);
  retainDirectory(path, cleanup == DirectoryCleanup::IfEmpty ? kIfEmpty : kWithContents);
}

void unregisterDirectory(const std::string& path) {
  std::lock_guard<std::mutex> lock(registryMutex);
  for (int kind : {kIfEmpty, kWithContents}) releaseDirectory(path, kind);
}

void registerChildProcess(int pid) {
  for (auto& child : children) {
    pid_t expected = 0;
    if (child.compare_exchange_strong(expected, pid_t(pid))) return;
  }
}

void unregisterChildProcess(int pid) {
  for (auto& child : children) {
    pid_t expected = pid_t(pid);
    if (child.compare_exchange_strong(expected, 0)) return;
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

SignalsHeld::SignalsHeld() {
  holdingSignals.store(true);
}

SignalsHeld::~SignalsHeld() {
  holdingSignals.store(false);
  if (const int signal = heldSignal.exchange(0)) removeTemporariesAndDie(signal);
}

ScratchDirectory::ScratchDirectory(const std::string& forOutput) {
  std::error_code ec;
  fs::path base = fs::temp_directory_path(ec);
  if (ec) base = "/tmp";
  std::string pattern = (base / (std::string(kScratchDirectoryPrefix) + "XXXXXX")).string();
  if (!::mkdtemp(pattern.data()))
    throw OutputError(forOutput,
                      "cannot create a scratch directory in '" + base.string() + "': " + std::strerror(errno));
  path_ = pattern;
  registerDirectory(path_, DirectoryCleanup::WithContents);
}

ScratchDirectory::~ScratchDirectory() {
  unregisterDirectory(path_);
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

}  // namespace texsynth
