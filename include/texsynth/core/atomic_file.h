#pragma once
// Atomic output: every writer writes to a temporary file beside the target and renames it
// into place only on success, so a failed run never leaves a half-written or clobbered file.
#include <functional>
#include <string>

namespace texsynth {

// Calls write(tempPath); on success renames tempPath to `path`, on any exception removes it
// and rethrows. Throws OutputError if the directory is missing or the rename fails.
void writeAtomically(const std::string& path, const std::function<void(const std::string& tempPath)>& write);

// Writes `bytes` to `path` atomically.
void writeFileAtomically(const std::string& path, const std::string& bytes);

// Reads a whole file; throws InputError if missing, unreadable or larger than maxBytes.
std::string readFileBytes(const std::string& path, std::size_t maxBytes = std::size_t(4) << 30);

// Lower-case extension without the dot ("png"), or "" if none.
std::string fileExtension(const std::string& path);

}  // namespace texsynth
