#include "server/relay/heap_trimmer.hpp"

#include <boost/asio/post.hpp>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mc::relay {

std::uint64_t HeapTrimmer::churn(const RelayStats& stats) {
  const std::uint64_t opened = stats.connections_total.load(std::memory_order_relaxed);
  const auto open = stats.clients.load(std::memory_order_relaxed);
  const std::uint64_t closed = open > 0 && static_cast<std::uint64_t>(open) <= opened ? opened - open : opened;
  return opened + closed;
}

bool HeapTrimmer::set_allocator_policy() {
#if defined(__GLIBC__)
  // Once per process; later calls (more relays in one test) change nothing.
  static const bool done = ::mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1;
  return done;
#else
  return false;
#endif
}

bool HeapTrimmer::trim() {
#if defined(__GLIBC__)
  ::malloc_trim(0);
  return true;
#else
  return false;
#endif
}

void HeapTrimmer::trim_now() {
  const auto t0 = std::chrono::steady_clock::now();
  if (!trim()) return;
  ++stats_.heap_trims;
  stats_.heap_trim_us += static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - t0).count());
}

void HeapTrimmer::arm() {
  timer_.expires_after(kPeriod);
  timer_.async_wait([self = shared_from_this()](boost::system::error_code ec) {
    if (ec) return;  // stopped
    const std::uint64_t now = churn(self->stats_);
    if (now != self->churn_at_last_trim_) {
      self->trim_now();
      self->churn_at_last_trim_ = now;
    }
    self->arm();
  });
}

void HeapTrimmer::stop() {
  boost::asio::post(timer_.get_executor(), [self = shared_from_this()] { self->timer_.cancel(); });
}

}  // namespace mc::relay
