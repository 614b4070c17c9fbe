// Counters shared by every session of one relay, read by /metrics and logs.
// Relaxed atomics: these are statistics, not synchronisation.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace mc::relay {

// A counter that every I/O thread bumps for every message it sends: one
// cache line per thread, so that the threads never fight over it (shared,
// the send path's counters bounced between the cores 2,500 times per frame
// per thread at 5,000 spectators). load() sums the lines.
template <class T>
class ShardedCounter {
 public:
  static constexpr std::size_t kShards = 16;
  ShardedCounter& operator+=(T v) {
    cells_[slot()].v.fetch_add(v, std::memory_order_relaxed);
    return *this;
  }
  ShardedCounter& operator-=(T v) {
    cells_[slot()].v.fetch_sub(v, std::memory_order_relaxed);
    return *this;
  }
  ShardedCounter& operator++() { return *this += 1; }
  T load() const {
    T sum = 0;
    for (const auto& c : cells_) sum += c.v.load(std::memory_order_relaxed);
    return sum;
  }

 private:
  // This thread's line: threads take lines in turn as they first count.
  static std::size_t slot() {
    static std::atomic<std::size_t> next{0};
    thread_local const std::size_t mine = next.fetch_add(1, std::memory_order_relaxed) % kShards;
    return mine;
  }
  struct alignas(64) Cell {
    std::atomic<T> v{0};
  };
  std::array<Cell, kShards> cells_{};
};

struct RelayStats {
  std::atomic<std::int64_t> clients{0};
  std::atomic<std::uint64_t> connections_total{0};
  // Bumped on every send, by every I/O thread: sharded.
  ShardedCounter<std::uint64_t> messages_sent;
  ShardedCounter<std::uint64_t> writes;  // socket writes: one per batch of messages
  // Batches the kernel took only part of at once (the rest waited for room):
  // a spectator reading slower than the stream, or a burst.
  ShardedCounter<std::uint64_t> partial_writes;
  ShardedCounter<std::uint64_t> bytes_sent;
  ShardedCounter<std::int64_t> queued_bytes;  // all spectators' send queues
  std::atomic<std::uint64_t> frames_dropped{0};
  std::atomic<std::uint64_t> closed_slow{0};
  std::atomic<std::uint64_t> refused_full{0};
  std::atomic<std::uint64_t> http_requests{0};
  std::atomic<std::uint64_t> http_not_found{0};
  std::atomic<std::uint64_t> inbound_rejected{0};
  std::atomic<std::uint64_t> refused_per_ip{0};
  std::atomic<std::uint64_t> refused_origin{0};
  // Heap trims (HeapTrimmer) and the time they took: what keeping the RSS
  // down after connections come and go costs the I/O thread.
  std::atomic<std::uint64_t> heap_trims{0};
  std::atomic<std::uint64_t> heap_trim_us{0};

  // Frame delay inside the relay: from publish to the end of its write to a
  // spectator, as a Prometheus histogram (upper bounds in ms, last = +Inf).
  static constexpr std::array<double, 11> kDelayBucketsMs{1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 5000};
  std::array<ShardedCounter<std::uint64_t>, kDelayBucketsMs.size() + 1> delay_buckets;
  ShardedCounter<std::uint64_t> delay_count;
  ShardedCounter<std::uint64_t> delay_sum_us;

  void record_delay(double ms) {
    std::size_t i = 0;
    while (i < kDelayBucketsMs.size() && ms > kDelayBucketsMs[i]) ++i;
    ++delay_buckets[i];
    ++delay_count;
    delay_sum_us += static_cast<std::uint64_t>(ms * 1000);
  }
};

}  // namespace mc::relay
