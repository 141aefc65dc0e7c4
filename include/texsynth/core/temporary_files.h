#pragma once
// The temporary files behind atomic writes. Each is named so that a later run recognizes it
// (".NAME.texsynth-tmp-HOST-PID-N.EXT" beside the target) and registered so that a catchable
// signal removes it before the process dies; one left by an uncatchable death (SIGKILL, power
// loss) is removed by the next write into its directory once its process is gone.
#include <string>
#include <string_view>

namespace texsynth {

// A fresh temporary name beside `target`, keeping the target's extension last (some writers
// pick the format from it).
std::string temporaryPathFor(const std::string& target);

// What marks a temporary's name, and the start of a ScratchDirectory's folder name.
inline constexpr std::string_view kTemporaryMarker = ".texsynth-tmp-";
inline constexpr std::string_view kScratchDirectoryPrefix = "texsynth-scratch-";

// True if `fileName` (no directory) is a temporary of an atomic write.
bool isTemporaryName(const std::string& fileName);

// The file name a temporary stands for ("NAME.EXT" for ".NAME.texsynth-tmp-HOST-PID-N.EXT"), or ""
// when `fileName` carries no temporary's marker.
std::string temporaryTargetName(const std::string& fileName);

// Signal-safe registry of the temporaries that exist right now. Their directories are kept too,
// so that a signal also finds the ones that did not fit the registry (a long animation stages
// thousands of frames): it removes every temporary of this process there.
void registerTemporary(const std::string& path);
void unregisterTemporary(const std::string& path);

// Directories a signal cleans up besides the temporaries: IfEmpty, the output directories a run
// created (removed deepest first, only when empty, so never anything we did not put there);
// WithContents, a private scratch directory (its files and then itself).
enum class DirectoryCleanup { IfEmpty, WithContents };
void registerDirectory(const std::string& path, DirectoryCleanup cleanup);
void unregisterDirectory(const std::string& path);

// Child processes (a video encoder writing one of our temporaries) that a signal kills first,
// so that nothing writes after the cleanup.
void registerChildProcess(int pid);
void unregisterChildProcess(int pid);

// On SIGINT, SIGTERM, SIGHUP and SIGQUIT: remove every registered temporary and directory, then
// die of the signal as before. SIGXFSZ is ignored, so a write past the file-size limit fails with an error
// (EFBIG) that the writer reports instead of killing the process. Idempotent.
void removeTemporariesOnSignals();

// While one exists, a caught signal waits: the process cleans up and dies of it only when the
// object goes. For a step that must not be cut in half (moving a run's outputs into place and
// saying so). One at a time.
class SignalsHeld {
 public:
  SignalsHeld();
  ~SignalsHeld();
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;
};

// Removes the temporaries in `directory` whose process is gone (same host, dead PID); returns
// how many. Done once per directory and process by every atomic write.
int removeStaleTemporaries(const std::string& directory);

// A private directory (mode 0700) under the system temp directory for scratch files a run reads
// back itself (a video's frames), removed with everything in it when the object goes or a signal
// ends the process. Throws
// OutputError naming `forOutput`, the output it serves, if it cannot be created.
class ScratchDirectory {
 public:
  explicit ScratchDirectory(const std::string& forOutput);
  ~ScratchDirectory();
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace texsynth
