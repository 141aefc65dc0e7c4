// A bounded in-memory store of job outputs.
#include "texsynth/studio/result_store.h"

namespace texsynth::studio {

std::string ResultStore::put(std::string contentType, std::string bytes) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string id = "result-" + std::to_string(++nextId_);
  results_.push_back({id, {std::move(contentType), std::move(bytes)}});
  while (results_.size() > keep_) results_.pop_front();
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
  std::size_t total = 0;
  for (const auto& entry : results_) total += entry.second.bytes.size();
  return total;
}

}  // namespace texsynth::studio
