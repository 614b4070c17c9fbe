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

bool HeapTrimmer::trim() {
#if defined(__GLIBC__)
  ::malloc_trim(0);
  return true;
#else
  return false;
#endif
}

void HeapTrimmer::arm() {
  timer_.expires_after(kPeriod);
  timer_.async_wait([self = shared_from_this()](boost::system::error_code ec) {
    if (ec) return;  // stopped
    const std::uint64_t now = churn(self->stats_);
    const bool since_trim = now != self->churn_at_last_trim_;
    const bool burst_over = now == self->churn_at_last_tick_;
    if (since_trim && (burst_over || now - self->churn_at_last_trim_ >= kMinChurn)) {
      trim();
      self->churn_at_last_trim_ = now;
    }
    self->churn_at_last_tick_ = now;
    self->arm();
  });
}

void HeapTrimmer::stop() {
  boost::asio::post(timer_.get_executor(), [self = shared_from_this()] { self->timer_.cancel(); });
}

}  // namespace mc::relay
