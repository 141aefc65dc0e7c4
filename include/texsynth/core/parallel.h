#pragma once
// Parallel loops on oneTBB. Work is split into fixed chunks whose results never
// depend on how many threads run them; `ThreadLimit` caps the thread count (--threads).
#include <cstdint>
#include <functional>
#include <memory>

namespace texsynth {

// Calls body(i) for i in [begin, end), in parallel. body must not depend on call order.
void parallelFor(std::int64_t begin, std::int64_t end, const std::function<void(std::int64_t)>& body,
                 std::int64_t grain = 1);

// Calls body(chunkBegin, chunkEnd) over [begin, end) in chunks of at most `grain`.
void parallelForChunks(std::int64_t begin, std::int64_t end, std::int64_t grain,
                       const std::function<void(std::int64_t, std::int64_t)>& body);

// Caps texsynth's worker threads while alive; 0 means all hardware threads.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

int hardwareThreads();

// The number of threads parallelFor may use now: the innermost ThreadLimit, else all cores.
// For libraries with pools of their own (OpenEXR), so they honour --threads too.
int threadLimit();

}  // namespace texsynth
