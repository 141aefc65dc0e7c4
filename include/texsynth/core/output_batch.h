#pragma once
// All-or-nothing outputs for a run that writes several files. While an OutputBatch is alive,
// every atomic write (writeAtomically and everything built on it: images, meshes, volumes,
// fields, reports) is staged as a finished temporary beside its target instead of being moved
// into place. commit() then moves them all, and undoes the ones already moved if a later one
// fails; a batch destroyed without commit (an error, a cancel) removes every staged file and
// every directory it created. A failed run thus never replaces a good file with a new one
// while another of its outputs is missing.
#include <string>
#include <vector>

namespace texsynth {

class OutputBatch {
 public:
  OutputBatch();  // becomes the active batch; one at a time
  ~OutputBatch();
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;

  // The batch writes are staged into, or nullptr.
  static OutputBatch* active();

  // A finished temporary file that becomes `target` on commit (replacing an earlier one for the
  // same target).
  void stage(const std::string& temporary, const std::string& target);

  // Creates `directory` and any missing parents now; the ones created are removed again, if
  // empty, unless the batch commits.
  void createDirectories(const std::string& directory);

  // Moves every staged file into place, all or none; throws OutputError naming the file that
  // could not be moved (after restoring the ones moved before it).
  void commit();

  std::size_t stagedCount() const { return staged_.size(); }

 private:
  struct Staged {
    std::string temporary, target;
  };
  void discard();
  std::vector<Staged> staged_;
  std::vector<std::string> createdDirectories_;  // parents first
  bool committed_ = false;
};

// Creates `directory` and any missing parents for a run's outputs: through the active batch (so
// they go again if the run fails), or at once without one. Throws OutputError if it cannot.
void createOutputDirectories(const std::string& directory);

}  // namespace texsynth
