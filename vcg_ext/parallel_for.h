// Independent tasks on a few threads, with progress and cancel from the calling thread
// (MeshLab's callback updates its GUI, so only that thread may call it).
#pragma once

#include "mesh_errors.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace vcg_ext {

/// The threads `threads` asks for: itself, or one per core where it is 0 or less.
inline int ThreadCount(int threads) {
  return threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

/// Runs work(i) for i in [0, count) on `threads` threads (0: one per core), this thread
/// included. After each task this thread runs, done(i, finished so far) is called on it. Once
/// it has no task left, idle(finished so far) is called on it about every 50 ms until the other
/// threads have finished theirs, and once when they have: a task elsewhere may wait on what only
/// this thread may ask (MeshLab's callback: whether the user pressed Stop), and the count still
/// moves to the end. Either returning false stops the others picking new tasks and throws
/// CancelledError. An exception from a task is rethrown here after every thread has stopped.
template <class Work, class Done, class Idle>
void ParallelFor(int count, int threads, Work work, Done done, Idle idle) {
  threads = std::max(1, std::min(ThreadCount(threads), count));
  std::atomic<int> next{0}, finished{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto run = [&](bool report) {
    for (int i; !stop && (i = next++) < count;) {
      try {
        work(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        stop = true;
        return;
      }
      const int n = ++finished;
      if (report && !done(i, n)) stop = true;
    }
  };
  std::mutex waiting;
  std::condition_variable others_done;
  int others = threads - 1;
  auto other = [&] {
    run(false);
    std::lock_guard<std::mutex> lock(waiting);
    if (--others == 0) others_done.notify_one();
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(other);
  run(true);
  {
    std::unique_lock<std::mutex> lock(waiting);
    while (!others_done.wait_for(lock, std::chrono::milliseconds(50), [&] { return others == 0; }))
      if (!stop) {
        lock.unlock();
        if (!idle(int(finished))) stop = true;
        lock.lock();
      }
  }
  for (auto& t : pool) t.join();
  if (threads > 1 && !stop && !idle(int(finished))) stop = true;
  if (error) std::rethrow_exception(error);
  if (stop) throw CancelledError();
}

/// ParallelFor with one progress(finished so far) for both: after each task this thread runs,
/// and while it waits for the others'.
template <class Work, class Progress>
void ParallelFor(int count, int threads, Work work, Progress progress) {
  ParallelFor(
      count, threads, work, [&progress](int, int finished) { return progress(finished); },
      progress);
}

/// ParallelFor with no progress and no stop.
template <class Work>
void ParallelFor(int count, int threads, Work work) {
  ParallelFor(count, threads, work, [](int) { return true; });
}

} // namespace vcg_ext
