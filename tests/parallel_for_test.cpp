// vcg_ext::ParallelFor: a stop asked for while the calling thread waits for the others' tasks.
#include <vcg_ext/parallel_for.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace {

using Clock = std::chrono::steady_clock;

TEST(ParallelFor, AStopAskedWhileWaitingForTheOtherThreadsReachesTheirTasks) {
  // The calling thread's task ends at once; the other thread's waits until the user's stop,
  // which only the calling thread may ask for (as MeshLab's callback), or 20 s.
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> other_started{false}, stop_asked{false}, released_by_stop{false};
  std::atomic<int> idle_calls{0}, done_calls{0};
  auto work = [&](int) {
    if (std::this_thread::get_id() == caller) {
      while (!other_started) std::this_thread::yield(); // the other thread has the other task
      return;
    }
    other_started = true;
    const auto until = Clock::now() + std::chrono::seconds(20);
    while (!stop_asked && Clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    released_by_stop = stop_asked.load();
  };
  auto done = [&](int, int) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    ++done_calls;
    return true;
  };
  auto idle = [&](int finished) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    EXPECT_EQ(finished, 1); // the calling thread's task
    if (++idle_calls == 3) stop_asked = true;
    return idle_calls < 3;
  };
  EXPECT_THROW(vcg_ext::ParallelFor(2, 2, work, done, idle), vcg_ext::CancelledError);
  EXPECT_TRUE(released_by_stop);
  EXPECT_EQ(idle_calls, 3);
  EXPECT_EQ(done_calls, 1);
}

TEST(ParallelFor, EveryTaskRunsOnceAndTheCountReachesTheEnd) {
  std::vector<std::atomic<int>> runs(100);
  for (auto& r : runs) r = 0;
  int last_done = 0;
  vcg_ext::ParallelFor(
      100, 4, [&](int i) { ++runs[size_t(i)]; },
      [&](int, int finished) {
        EXPECT_GT(finished, last_done); // the count only grows
        last_done = finished;
        return true;
      },
      [&](int finished) {
        EXPECT_GE(finished, last_done);
        last_done = finished;
        return true;
      });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
  EXPECT_EQ(last_done, 100); // the end is reported, whichever thread finished last
}

TEST(ParallelFor, TheCountReachesTheEndWhenAnotherThreadFinishesLast) {
  // The calling thread's task ends as soon as the other thread has the other task, which ends
  // 200 ms later: only the call after the wait can report both done.
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> other_started{false};
  int last_reported = 0;
  vcg_ext::ParallelFor(
      2, 2,
      [&](int) {
        if (std::this_thread::get_id() == caller) {
          while (!other_started) std::this_thread::yield();
          return;
        }
        other_started = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
      },
      [&](int, int finished) {
        last_reported = finished;
        return true;
      },
      [&](int finished) {
        last_reported = finished;
        return true;
      });
  EXPECT_EQ(last_reported, 2);
}

} // namespace
