#pragma once
// The studio's synthesis workers. Every job runs in a named lane ("preview", "cut", ...); a newer
// job in a lane supersedes the older one there: a job still waiting is dropped, a running one is
// cancelled through its Progress (the synthesis stops at its next progress step; a lazy solid
// keeps the levels it finished). So moving a cut plane quickly never queues obsolete work.
// Job states, progress and failures go out as events: "job" {id, lane, state, seconds, error}
// with state queued | running | done | failed | cancelled | superseded, and "progress"
// {job, stage, done, total} at most ten times a second per job.
#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "texsynth/core/progress.h"
#include "texsynth/studio/event_hub.h"

namespace texsynth::studio {

class JobLanes {
 public:
  // The job's work; `jobId` names it in the events it publishes itself (results).
  using Work = std::function<void(Progress& progress, const std::string& jobId)>;

  // `workers` >= 1 threads.
  JobLanes(int workers, EventHub& events);
  // Cancels what runs, drops what waits, joins the workers.
  ~JobLanes();
  JobLanes(const JobLanes&) = delete;
  JobLanes& operator=(const JobLanes&) = delete;

  // Queues `work` in `lane`, superseding the lane's older job; returns the new job's id.
  std::string submit(const std::string& lane, Work work);
  // Blocks until no job waits or runs (tests, shutdown).
  void waitIdle();

 private:
  class JobProgress;
  struct Job {
    std::string id, lane;
    Work work;
    std::shared_ptr<JobProgress> progress;
  };
  void workerLoop();
  void publishState(const Job& job, const std::string& state, double seconds = 0, const std::string& error = {});

  EventHub& events_;
  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<Job> waiting_;
  std::map<std::string, std::shared_ptr<JobProgress>> running_;  // by lane
  int busy_ = 0;
  std::int64_t nextId_ = 0;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace texsynth::studio
