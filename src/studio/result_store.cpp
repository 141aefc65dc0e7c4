// A bounded in-memory store of job outputs.
#include "texsynth/studio/result_store.h"

namespace texsynth::studio {

std::string ResultStore::put(std::string contentType, std::string bytes) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string id = "result-" + std::to_string(++nextId_);
  bytes_ += bytes.size();
  results_.push_back({id, {std::move(contentType), std::move(bytes)}});
  while (results_.size() > keep_ || (bytes_ > maxBytes_ && results_.size() > 1)) {
    bytes_ -= results_.front().second.bytes.size();
    results_.pop_front();
  }
  return id;
}

std::optional<StoredResult> ResultStore::get(const std::string& id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [key, result] : results_)
    if (key == id) return result;
  return std::nullopt;
}

std::size_t ResultStore::bytes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return bytes_;
}

}  // namespace texsynth::studio
