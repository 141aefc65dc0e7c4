#pragma once
// The studio's push channel: events (job states, progress, results, scene changes) numbered in
// order and kept for a while, so that a page that reconnects with the last id it saw
// (Server-Sent Events' Last-Event-ID) misses nothing still kept.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace texsynth::studio {

struct StudioEvent {
  std::int64_t id = 0;  // 1, 2, ... in publication order
  std::string type;     // "job", "progress", "result", "scene", "field"
  nlohmann::json data;
};

class EventHub {
 public:
  // Keeps the newest `keep` events (>= 1) for late readers.
  explicit EventHub(std::size_t keep = 1024);

  // Thread-safe; returns the event's id.
  std::int64_t publish(const std::string& type, nlohmann::json data);
  // The kept events with id > after, waiting up to `timeout` for a first one; empty on timeout
  // or once closed.
  std::vector<StudioEvent> waitAfter(std::int64_t after, std::chrono::milliseconds timeout);
  // The first event with id > after, kept or still to come, that `match` accepts; nothing once
  // `timeout` has passed or the hub is closed.
  std::optional<StudioEvent> waitFor(const std::function<bool(const StudioEvent&)>& match,
                                     std::chrono::milliseconds timeout, std::int64_t after = 0);
  std::int64_t lastId() const;
  // Wakes every reader and makes them stop (server shutdown).
  void close();
  bool closed() const;

 private:
  const std::size_t keep_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<StudioEvent> events_;
  std::int64_t lastId_ = 0;
  bool closed_ = false;
};

// "id: N\nevent: TYPE\ndata: JSON\n\n", the wire form of one Server-Sent Event.
std::string formatServerSentEvent(const StudioEvent& event);

}  // namespace texsynth::studio
