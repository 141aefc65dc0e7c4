#include "texsynth/core/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include "texsynth/core/error.h"

namespace texsynth {

void parallelFor(std::int64_t begin, std::int64_t end, const std::function<void(std::int64_t)>& body,
                 std::int64_t grain) {
  parallelForChunks(begin, end, grain, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t i = b; i < e; ++i) body(i);
  });
}

void parallelForChunks(std::int64_t begin, std::int64_t end, std::int64_t grain,
                       const std::function<void(std::int64_t, std::int64_t)>& body) {
  if (end <= begin) return;
  if (grain < 1) grain = 1;
  // One chunk runs here: waking the pool's threads for it costs more than small work itself
  // (tens of microseconds per call in a VM; a multigrid cycle makes hundreds of such calls).
  if (end - begin <= grain) return body(begin, end);
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(begin, end, grain),
                    [&](const tbb::blocked_range<std::int64_t>& r) { body(r.begin(), r.end()); });
}

struct ThreadLimit::Impl {
  std::unique_ptr<tbb::global_control> control;
};

ThreadLimit::ThreadLimit(int threads) : impl_(std::make_unique<Impl>()) {
  if (threads < 0)
    throw ParameterError("--threads", "must be 0 (all) or a positive count, got " + std::to_string(threads));
  if (threads > 0)
    impl_->control =
        std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
}

ThreadLimit::~ThreadLimit() = default;

int hardwareThreads() {
  return tbb::info::default_concurrency();
}

int threadLimit() {
  return int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

}  // namespace texsynth
