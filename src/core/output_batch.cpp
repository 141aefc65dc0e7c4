#include "texsynth/core/output_batch.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>

#include "texsynth/core/error.h"
#include "texsynth/core/temporary_files.h"

namespace texsynth {
namespace fs = std::filesystem;

namespace {
std::atomic<OutputBatch*> activeBatch{nullptr};

void removeTemporary(const std::string& path) {
  std::error_code ec;
  fs::remove(path, ec);
  unregisterTemporary(path);
}
}  // namespace

OutputBatch::OutputBatch() {
  OutputBatch* expected = nullptr;
  if (!activeBatch.compare_exchange_strong(expected, this)) throw InternalError("nested OutputBatch");
}

OutputBatch::~OutputBatch() {
  if (!committed_) discard();
  activeBatch.store(nullptr);
}

OutputBatch* OutputBatch::active() {
  return activeBatch.load();
}

void OutputBatch::stage(const std::string& temporary, const std::string& target) {
  for (Staged& s : staged_)
    if (s.target == target) {
      removeTemporary(s.temporary);
      s.temporary = temporary;
      return;
    }
  staged_.push_back({temporary, target});
}

void OutputBatch::createDirectories(const std::string& directory) {
  std::vector<fs::path> missing;  // deepest first
  std::error_code ec;
  for (fs::path p = fs::absolute(directory, ec); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && !fs::is_directory(*it))
      throw OutputError(directory, "cannot create the directory: " + ec.message());
    createdDirectories_.push_back(it->string());
    registerDirectory(it->string(), DirectoryCleanup::IfEmpty);  // a signal removes it too
  }
}

void OutputBatch::discard() {
  for (const Staged& s : staged_) removeTemporary(s.temporary);
  staged_.clear();
  std::error_code ec;
  for (auto it = createdDirectories_.rbegin(); it != createdDirectories_.rend(); ++it) {
    fs::remove(*it, ec);  // only if empty: never anything we did not put there
    unregisterDirectory(*it);
  }
  createdDirectories_.clear();
}

void OutputBatch::commit() {
  // Each replaced file is first kept under a temporary name (a hard link where the file system
  // has them, so the target never disappears), so a failure part way through can put every
  // earlier one back.
  struct Moved {
    const Staged* file;
    std::string backup;  // empty: the target did not exist before
  };
  std::vector<Moved> moved;
  const auto rollBack = [&moved] {
    std::error_code ec;
    for (auto it = moved.rbegin(); it != moved.rend(); ++it) {
      if (it->backup.empty())
        fs::remove(it->file->target, ec);
      else
        fs::rename(it->backup, it->file->target, ec);
      unregisterTemporary(it->backup);
    }
  };
  // Throws after undoing everything; `target` is copied first, since discard() frees staged_.
  const auto fail = [&](std::string target, const std::string& problem) {
    rollBack();
    discard();
    throw OutputError(target, problem);
  };
  for (const Staged& s : staged_) {
    std::error_code ec;
    std::string backup;
    if (fs::exists(s.target, ec) && !fs::is_regular_file(s.target, ec))  // appeared while the run worked
      fail(s.target, "exists and is not a regular file; nothing was written");
    if (fs::exists(s.target, ec)) {
      backup = temporaryPathFor(s.target);
      registerTemporary(backup);
      if (::link(s.target.c_str(), backup.c_str()) != 0) {
        fs::rename(s.target, backup, ec);  // no hard links here: keep it aside instead
        if (ec) {
          unregisterTemporary(backup);
          fail(s.target, "cannot replace the existing file: " + ec.message());
        }
      }
    }
    fs::rename(s.temporary, s.target, ec);
    if (ec) {
      const std::string problem = "cannot move the finished file into place: " + ec.message();
      if (!backup.empty()) fs::rename(backup, s.target, ec);  // a backup moved aside goes back
      unregisterTemporary(backup);
      fail(s.target, problem);
    }
    unregisterTemporary(s.temporary);
    moved.push_back({&s, backup});
  }
  for (const Moved& m : moved)
    if (!m.backup.empty()) removeTemporary(m.backup);
  staged_.clear();
  for (const std::string& directory : createdDirectories_) unregisterDirectory(directory);
  createdDirectories_.clear();
  committed_ = true;
}

void createOutputDirectories(const std::string& directory) {
  if (OutputBatch* batch = OutputBatch::active()) return batch->createDirectories(directory);
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (!fs::is_directory(directory, ec)) throw OutputError(directory, "cannot create the directory: " + ec.message());
}

}  // namespace texsynth
