#pragma once
// Atomic output: every writer writes to a temporary file beside the target (temporary_files.h)
// and renames it into place only on success, so a failed write never leaves a half-written or
// clobbered file. Inside an OutputBatch (output_batch.h) the rename waits for the batch's commit,
// so a run's outputs appear all together or not at all.
#include <functional>
#include <string>

namespace texsynth {

// WithRun: part of the active OutputBatch, if any. Immediately: moved into place at once even
// inside a batch (caches, which stay valid whatever happens to the run).
enum class Staging { WithRun, Immediately };

// Calls write(tempPath); on success renames tempPath to `path` (or stages it), on any exception
// removes it and rethrows (a foreign exception as OutputError naming `path`). Throws OutputError
// if the destination cannot be written or the rename fails.
void writeAtomically(const std::string& path, const std::function<void(const std::string& tempPath)>& write,
                     Staging staging = Staging::WithRun);

// Writes `bytes` to `path` atomically.
void writeFileAtomically(const std::string& path, const std::string& bytes, Staging staging = Staging::WithRun);

// Throws OutputError unless a file could be written at `path`: its directory exists and is
// writable, and it is not a directory or other non-regular file. For checks before any work.
void checkWritableDestination(const std::string& path);

// Reads a whole file; throws InputError if missing, unreadable or larger than maxBytes.
std::string readFileBytes(const std::string& path, std::size_t maxBytes = std::size_t(4) << 30);

// Lower-case extension without the dot ("png"), or "" if none.
std::string fileExtension(const std::string& path);

}  // namespace texsynth
