// Numbered studio events, kept in a bounded window, with blocking reads for the SSE stream.
#include "texsynth/studio/event_hub.h"

#include <algorithm>

namespace texsynth::studio {

EventHub::EventHub(std::size_t keep) : keep_(std::max<std::size_t>(keep, 1)) {}

std::int64_t EventHub::publish(const std::string& type, nlohmann::json data) {
  std::int64_t id;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    id = ++lastId_;
    events_.push_back({id, type, std::move(data)});
    if (events_.size() > keep_) events_.pop_front();
  }
  changed_.notify_all();
  return id;
}

std::vector<StudioEvent> EventHub::waitAfter(std::int64_t after, std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return closed_ || lastId_ > after; });
  std::vector<StudioEvent> out;
  if (closed_) return out;
  for (const StudioEvent& event : events_)
    if (event.id > after) out.push_back(event);
  return out;
}

std::optional<StudioEvent> EventHub::waitFor(const std::function<bool(const StudioEvent&)>& match,
                                             std::chrono::milliseconds timeout, std::int64_t after) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (auto now = std::chrono::steady_clock::now(); now < deadline && !closed(); now = std::chrono::steady_clock::now())
    for (const StudioEvent& event :
         waitAfter(after, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now))) {
      if (match(event)) return event;
      after = event.id;
    }
  return std::nullopt;
}

std::int64_t EventHub::lastId() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return lastId_;
}

void EventHub::close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

bool EventHub::closed() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return closed_;
}

std::string formatServerSentEvent(const StudioEvent& event) {
  return "id: " + std::to_string(event.id) + "\nevent: " + event.type + "\ndata: " + event.data.dump() + "\n\n";
}

}  // namespace texsynth::studio
