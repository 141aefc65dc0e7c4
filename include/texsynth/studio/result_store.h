#pragma once
// Finished job outputs (vertex colours, cut meshes) held in memory under generated ids until the
// page fetches them; only the newest few are kept, and at most so many bytes (a cut of a large model
// is tens of MiB), so a long session does not grow.
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>

namespace texsynth::studio {

struct StoredResult {
  std::string contentType;
  std::string bytes;
};

class ResultStore {
 public:
  // Keeps the newest `keep` results while they hold at most `maxBytes` (the newest one always).
  explicit ResultStore(std::size_t keep = 32, std::size_t maxBytes = std::size_t(256) << 20)
      : keep_(keep), maxBytes_(maxBytes) {}
  // Returns the new result's id ("result-N").
  std::string put(std::string contentType, std::string bytes);
  // A copy of the result, or nothing for an unknown or evicted id.
  std::optional<StoredResult> get(const std::string& id) const;
  // Bytes held now.
  std::size_t bytes() const;

 private:
  const std::size_t keep_, maxBytes_;
  mutable std::mutex mutex_;
  std::deque<std::pair<std::string, StoredResult>> results_;
  std::size_t bytes_ = 0;
  std::int64_t nextId_ = 0;
};

}  // namespace texsynth::studio
