#include "server_pool.h"

#include <tuple>

namespace curvature_inpaint {

ServerPool::ServerPool(std::vector<std::string> urls, int per_server, double set_aside_s)
    : urls_(std::move(urls)), per_server_(std::max(1, per_server)), set_aside_(set_aside_s),
      in_flight_(urls_.size(), 0), answered_(urls_.size(), 0),
      set_aside_until_(urls_.size(), Clock::time_point()) {}

int ServerPool::Acquire(const std::set<int>& tried) {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    // The best untried server with a free slot: one not set aside, the least busy, the one
    // that has answered least; a server set aside only when no other is left.
    const Clock::time_point now = Clock::now();
    int best = -1;
    std::tuple<bool, int, int> best_rank;
    for (int i = 0; i < int(urls_.size()); ++i) {
      if (tried.count(i) || in_flight_[size_t(i)] >= per_server_) continue;
      const std::tuple<bool, int, int> rank(set_aside_until_[size_t(i)] > now,
                                            in_flight_[size_t(i)], answered_[size_t(i)]);
      if (best < 0 || rank < best_rank) best = i, best_rank = rank;
    }
    if (best >= 0) {
      ++in_flight_[size_t(best)];
      return best;
    }
    freed_.wait(lock);
  }
}

void ServerPool::Release(int server, bool ok) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    --in_flight_[size_t(server)];
    if (ok)
      ++answered_[size_t(server)];
    else
      set_aside_until_[size_t(server)] =
          Clock::now() + std::chrono::duration_cast<Clock::duration>(set_aside_);
  }
  freed_.notify_all();
}

std::vector<QImage> ServerPool::Inpaint(const QImage& image, const QImage& mask,
                                        const InpaintParams& params) {
  std::set<int> tried;
  std::string last;
  for (;;) {
    const int server = Acquire(tried);
    InpaintParams one = params;
    one.url = urls_[size_t(server)];
    one.urls.clear();
    one.pool = nullptr;
    try {
      std::vector<QImage> out = curvature_inpaint::Inpaint(image, mask, one);
      Release(server, true);
      return out;
    } catch (const InpaintError& e) {
      Release(server, false);
      tried.insert(server);
      last = e.what();
      if (tried.size() == urls_.size())
        throw InpaintError("every one of the " + std::to_string(urls_.size()) +
                           " servers failed; the last: " + last);
    } catch (...) {
      // A stop the user asked for (CancelledError) is no failure of the server: it is handed
      // back unblamed and the next one is not tried.
      Release(server, true);
      throw;
    }
  }
}

std::vector<int> ServerPool::Answered() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return answered_;
}

} // namespace curvature_inpaint
