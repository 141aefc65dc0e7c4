// Worker threads for studio jobs, one live job per lane, with cancellation by supersession.
#include "texsynth/studio/job_lanes.h"

#include <algorithm>
#include <chrono>

#include "texsynth/core/error.h"

namespace texsynth::studio {

// Progress that publishes "progress" events (throttled) and is cancelled when superseded.
class JobLanes::JobProgress : public Progress {
 public:
  JobProgress(EventHub& events, std::string job) : events_(events), job_(std::move(job)) {}
  void begin(const std::string& stage, std::int64_t total) override {
    throwIfCancelled();
    std::lock_guard<std::mutex> lock(mutex_);
    stage_ = stage, total_ = total, done_ = 0;
    publishLocked(true);
  }
  void advance(std::int64_t units) override {
    throwIfCancelled();
    std::lock_guard<std::mutex> lock(mutex_);
    done_ += units;
    publishLocked(false);
  }
  void end() override {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = total_;
    publishLocked(true);
  }

 private:
  void publishLocked(bool always) {
    const auto now = std::chrono::steady_clock::now();
    if (!always && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    events_.publish("progress", {{"job", job_}, {"stage", stage_}, {"done", done_}, {"total", total_}});
  }
  EventHub& events_;
  const std::string job_;
  std::mutex mutex_;
  std::string stage_;
  std::int64_t done_ = 0, total_ = 0;
  std::chrono::steady_clock::time_point last_{};
};

JobLanes::JobLanes(int workers, EventHub& events) : events_(events) {
  if (workers < 1) throw ParameterError("workers", "must be at least 1, got " + std::to_string(workers));
  for (int i = 0; i < workers; ++i) workers_.emplace_back([this] { workerLoop(); });
}

JobLanes::~JobLanes() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    for (const Job& job : waiting_) publishState(job, "cancelled");
    waiting_.clear();
    for (auto& [lane, progress] : running_) progress->cancel();
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

std::string JobLanes::submit(const std::string& lane, Work work) {
  Job job;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job.id = "job-" + std::to_string(++nextId_);
    job.lane = lane;
    job.work = std::move(work);
    job.progress = std::make_shared<JobProgress>(events_, job.id);
    const auto older = std::find_if(waiting_.begin(), waiting_.end(), [&](const Job& j) { return j.lane == lane; });
    if (older != waiting_.end()) {
      publishState(*older, "superseded");
      waiting_.erase(older);
    }
    if (const auto running = running_.find(lane); running != running_.end()) running->second->cancel();
    publishState(job, "queued");
    waiting_.push_back(job);
  }
  wake_.notify_one();
  return job.id;
}

void JobLanes::waitIdle() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [&] { return waiting_.empty() && busy_ == 0; });
}

void JobLanes::workerLoop() {
  for (;;) {
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      // A lane's job waits while the lane's superseded job is still winding down.
      const auto startable = [&] {
        return std::find_if(waiting_.begin(), waiting_.end(), [&](const Job& j) { return !running_.count(j.lane); });
      };
      wake_.wait(lock, [&] { return stopping_ || startable() != waiting_.end(); });
      if (stopping_) return;
      const auto next = startable();
      job = std::move(*next);
      waiting_.erase(next);
      running_[job.lane] = job.progress;
      ++busy_;
      publishState(job, "running");
    }
    const auto started = std::chrono::steady_clock::now();
    std::string state = "done", error;
    try {
      job.work(*job.progress, job.id);
    } catch (const Cancelled&) {
      state = "cancelled";
    } catch (const std::exception& e) {
      state = "failed", error = e.what();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      publishState(job, state, seconds, error);
      running_.erase(job.lane);
      --busy_;
    }
    wake_.notify_all();
    idle_.notify_all();
  }
}

void JobLanes::publishState(const Job& job, const std::string& state, double seconds, const std::string& error) {
  nlohmann::json data = {{"id", job.id}, {"lane", job.lane}, {"state", state}};
  if (seconds > 0) data["seconds"] = seconds;
  if (!error.empty()) data["error"] = error;
  events_.publish("job", std::move(data));
}

}  // namespace texsynth::studio
