// Counters shared by every session of one relay, read by /metrics and logs.
// Relaxed atomics: these are statistics, not synchronisation.
#pragma once

#include <atomic>
#include <cstdint>

namespace mc::relay {

struct RelayStats {
  std::atomic<std::int64_t> clients{0};
  std::atomic<std::uint64_t> connections_total{0};
  std::atomic<std::uint64_t> messages_sent{0};
  std::atomic<std::uint64_t> bytes_sent{0};
  std::atomic<std::uint64_t> frames_dropped{0};
  std::atomic<std::uint64_t> closed_slow{0};
  std::atomic<std::uint64_t> refused_full{0};
  std::atomic<std::uint64_t> http_requests{0};
  std::atomic<std::uint64_t> http_not_found{0};
  std::atomic<std::uint64_t> inbound_rejected{0};
};

}  // namespace mc::relay
