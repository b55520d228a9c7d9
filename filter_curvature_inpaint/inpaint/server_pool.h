// A pool of inpainting servers for one run (several GPU machines, each with a Stable
// Diffusion server): the holes' requests are spread over them with at most `per_server` in
// flight on each (one is what such a server does best), a server that fails or times out is
// set aside for a while and the request goes to another, and a request fails only when every
// server has failed it. A hole's variations are whatever one server answers for its seed, so
// they come back the same whichever server answers.
#pragma once

#include "inpainter.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace curvature_inpaint {

class ServerPool {
public:
  /// `urls` (at least one) of servers of one backend.
  ServerPool(std::vector<std::string> urls, int per_server, double set_aside_s = 30);

  /// Requests that can be in flight at once.
  int Capacity() const { return int(urls_.size()) * per_server_; }

  /// Inpaint() on one of the servers (params.url replaced, params.pool ignored); on an
  /// InpaintError the next untried server, best first. Throws InpaintError naming the last
  /// server's error when every server failed. A stop asked for through params.http.cancelled
  /// (vcg_ext::CancelledError) is no server's failure: it passes through without trying
  /// another server. Thread-safe.
  std::vector<QImage> Inpaint(const QImage& image, const QImage& mask, const InpaintParams& params);

  /// Per server: the requests it answered.
  std::vector<int> Answered() const;

private:
  using Clock = std::chrono::steady_clock;
  int Acquire(const std::set<int>& tried);
  void Release(int server, bool ok);

  std::vector<std::string> urls_;
  int per_server_;
  std::chrono::duration<double> set_aside_;
  mutable std::mutex mutex_;
  std::condition_variable freed_;
  std::vector<int> in_flight_, answered_;
  std::vector<Clock::time_point> set_aside_until_;
};

} // namespace curvature_inpaint
