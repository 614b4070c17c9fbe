// Counters shared by every session of one relay, read by /metrics and logs.
// Relaxed atomics: these are statistics, not synchronisation.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

namespace mc::relay {

struct RelayStats {
  std::atomic<std::int64_t> clients{0};
  std::atomic<std::uint64_t> connections_total{0};
  std::atomic<std::uint64_t> messages_sent{0};
  std::atomic<std::uint64_t> writes{0};  // socket writes: one per batch of messages
  std::atomic<std::uint64_t> bytes_sent{0};
  std::atomic<std::uint64_t> frames_dropped{0};
  std::atomic<std::uint64_t> closed_slow{0};
  std::atomic<std::uint64_t> refused_full{0};
  std::atomic<std::uint64_t> http_requests{0};
  std::atomic<std::uint64_t> http_not_found{0};
  std::atomic<std::uint64_t> inbound_rejected{0};
  std::atomic<std::uint64_t> refused_per_ip{0};
  std::atomic<std::uint64_t> refused_origin{0};
  std::atomic<std::int64_t> queued_bytes{0};  // all spectators' send queues

  // Frame delay inside the relay: from publish to the end of its write to a
  // spectator, as a Prometheus histogram (upper bounds in ms, last = +Inf).
  static constexpr std::array<double, 11> kDelayBucketsMs{1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 5000};
  std::array<std::atomic<std::uint64_t>, kDelayBucketsMs.size() + 1> delay_buckets{};
  std::atomic<std::uint64_t> delay_count{0};
  std::atomic<std::uint64_t> delay_sum_us{0};

  void record_delay(double ms) {
    std::size_t i = 0;
    while (i < kDelayBucketsMs.size() && ms > kDelayBucketsMs[i]) ++i;
    delay_buckets[i].fetch_add(1, std::memory_order_relaxed);
    delay_count.fetch_add(1, std::memory_order_relaxed);
    delay_sum_us.fetch_add(static_cast<std::uint64_t>(ms * 1000), std::memory_order_relaxed);
  }
};

}  // namespace mc::relay
