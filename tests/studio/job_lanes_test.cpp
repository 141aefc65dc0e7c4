// Studio jobs: a newer job in a lane supersedes a waiting one and cancels a running one; lanes run
// side by side; failures are reported, not thrown.
#include "texsynth/studio/job_lanes.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace texsynth::studio {
namespace {

std::string finalState(EventHub& events, const std::string& job) {
  std::string state;
  for (const StudioEvent& e : events.waitAfter(0, std::chrono::milliseconds(0)))
    if (e.type == "job" && e.data["id"] == job) state = e.data["state"];
  return state;
}

TEST(JobLanes, ANewerJobSupersedesAndCancelsTheOlder) {
  EventHub events;
  std::atomic<bool> started{false};
  std::atomic<int> ran{0};
  {
    JobLanes jobs(1, events);
    // The first job runs until cancelled (its progress throws Cancelled once superseded).
    const std::string first = jobs.submit("cut", [&](Progress& progress, const std::string&) {
      started = true;
      progress.begin("spin", 1000000);
      for (;;) {
        progress.advance(1);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    });
    while (!started) std::this_thread::yield();
    const std::string second = jobs.submit("cut", [&](Progress&, const std::string&) { ran += 10; });
    const std::string third = jobs.submit("cut", [&](Progress&, const std::string&) { ran += 1; });
    jobs.waitIdle();
    EXPECT_EQ(finalState(events, first), "cancelled");
    EXPECT_EQ(finalState(events, second), "superseded");
    EXPECT_EQ(finalState(events, third), "done");
    EXPECT_EQ(ran, 1) << "only the newest ran";
  }
}

TEST(JobLanes, LanesRunSideBySideAndFailuresAreEvents) {
  EventHub events;
  JobLanes jobs(2, events);
  std::atomic<int> inside{0}, most{0};
  const auto work = [&](Progress&, const std::string&) {
    most = std::max(most.load(), ++inside);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    --inside;
  };
  jobs.submit("preview", work);
  jobs.submit("cut", work);
  const std::string failing =
      jobs.submit("export", [](Progress&, const std::string&) { throw std::runtime_error("disk full"); });
  jobs.waitIdle();
  EXPECT_EQ(most, 2);
  EXPECT_EQ(finalState(events, failing), "failed");
  for (const StudioEvent& e : events.waitAfter(0, std::chrono::milliseconds(0)))
    if (e.type == "job" && e.data["id"] == failing && e.data["state"] == "failed") {
      EXPECT_EQ(e.data["error"], "disk full");
    }
}

TEST(EventHub, KeepsTheNewestAndWakesReaders) {
  EventHub events(3);
  for (int i = 0; i < 5; ++i) events.publish("tick", {{"i", i}});
  const auto kept = events.waitAfter(0, std::chrono::milliseconds(0));
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept.front().id, 3);
  std::thread later([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    events.publish("tock", nlohmann::json::object());
  });
  const auto woken = events.waitAfter(5, std::chrono::seconds(10));
  later.join();
  ASSERT_EQ(woken.size(), 1u);
  EXPECT_EQ(formatServerSentEvent(woken[0]), "id: 6\nevent: tock\ndata: {}\n\n");
  const auto found = events.waitFor([](const StudioEvent& e) { return e.type == "tick" && e.data["i"] == 3; },
                                    std::chrono::seconds(1));
  ASSERT_TRUE(found);
  EXPECT_EQ(found->id, 4);
  EXPECT_FALSE(events.waitFor([](const StudioEvent& e) { return e.type == "never"; }, std::chrono::milliseconds(50)));
  events.close();
  EXPECT_TRUE(events.waitAfter(0, std::chrono::seconds(10)).empty()) << "closed: readers return at once";
}

}  // namespace
}  // namespace texsynth::studio
