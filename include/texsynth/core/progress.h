#pragma once
// Progress reporting for long work: a stage name, done/total, and a way to cancel.
// Algorithms take a Progress& and call begin/advance; the CLI draws a bar on stderr.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace texsynth {

class Progress {
 public:
  virtual ~Progress() = default;
  // Starts a stage of `total` units of work.
  virtual void begin(const std::string& stage, std::int64_t total) = 0;
  // Reports `units` more units done (thread-safe). Throws Cancelled if cancel() was called.
  virtual void advance(std::int64_t units = 1) = 0;
  // Ends the current stage.
  virtual void end() = 0;
  void cancel() { cancelled_ = true; }
  bool cancelled() const { return cancelled_; }

 protected:
  void throwIfCancelled() const;

 private:
  std::atomic<bool> cancelled_{false};
};

// Reports nothing; still honours cancel().
class NullProgress : public Progress {
 public:
  void begin(const std::string&, std::int64_t) override {}
  void advance(std::int64_t) override { throwIfCancelled(); }
  void end() override {}
};

// A bar on stderr, redrawn at most ~10 times a second; silent when stderr is not a terminal
// unless `force` is set, in which case it prints one line per stage.
class ConsoleProgress : public Progress {
 public:
  explicit ConsoleProgress(bool force = false);
  void begin(const std::string& stage, std::int64_t total) override;
  void advance(std::int64_t units) override;
  void end() override;

 private:
  void draw(bool final);
  std::mutex mutex_;
  std::string stage_;
  std::atomic<std::int64_t> done_{0};
  std::int64_t total_ = 0;
  bool terminal_ = false;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

// A process-wide no-op progress, for callers that do not care.
Progress& noProgress();

}  // namespace texsynth
