#pragma once
// The first check of every input file, before its type or format is looked at: a missing file or
// a directory is then reported as that, not as an unknown file type or an unreadable format.
#include <string>

namespace texsynth {

// Throws InputError(path, ...) unless `path` names an existing, readable regular file (a
// symbolic link to one is fine): "file does not exist", "is a directory, not a file", "is not a
// regular file" or "cannot be read: <reason>".
void requireReadableFile(const std::string& path);

}  // namespace texsynth
