#include "texsynth/core/progress.h"

#include <unistd.h>

#include <cstdio>

#include "texsynth/core/error.h"

namespace texsynth {

void Progress::throwIfCancelled() const {
  if (cancelled_) throw Cancelled();
}

Progress& noProgress() {
  static NullProgress instance;
  return instance;
}

ConsoleProgress::ConsoleProgress(bool force) : terminal_(isatty(fileno(stderr)) != 0 || force) {}

void ConsoleProgress::begin(const std::string& stage, std::int64_t total) {
  std::lock_guard lock(mutex_);
  stage_ = stage;
  total_ = total;
  done_ = 0;
  start_ = lastDraw_ = std::chrono::steady_clock::now();
}

void ConsoleProgress::advance(std::int64_t units) {
  throwIfCancelled();
  done_ += units;
  if (!terminal_) return;
  auto now = std::chrono::steady_clock::now();
  if (now - lastDraw_ < std::chrono::milliseconds(100)) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  lastDraw_ = now;
  draw(false);
}

void ConsoleProgress::end() {
  std::lock_guard lock(mutex_);
  if (terminal_) draw(true);
}

void ConsoleProgress::draw(bool final) {
  const int width = 30;
  std::int64_t done = final ? total_ : done_.load();
  double fraction = total_ > 0 ? double(done) / double(total_) : 1.0;
  if (fraction > 1) fraction = 1;
  int filled = int(fraction * width);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "\r%-28.28s [", stage_.c_str());
  for (int i = 0; i < width; ++i) std::fputc(i < filled ? '#' : '.', stderr);
  std::fprintf(stderr, "] %3d%% %6.1fs%s", int(fraction * 100), seconds, final ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace texsynth
