// What an edge adds to its /metrics (server/nats/README.md, "Edge
// metrics"): the NATS link, snapshot reads, games asked for, the lag behind
// the origin, and each game's EdgeSync counters. A plain report, rendered
// as Prometheus text without any I/O, so it is tested without NATS.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "server/nats/edge_sync.hpp"

namespace mc::nats {

struct EdgeReport {
  bool connected = false;           // the NATS link is up
  std::uint64_t messages_in = 0;    // NATS messages received (live, replies)
  std::uint64_t bytes_in = 0;       // their payload bytes
  std::uint64_t reconnects = 0;     // successful reconnects
  std::uint64_t fetches_found = 0;  // snapshot reads that found one
  std::uint64_t fetches_not_found = 0;
  std::uint64_t fetches_failed = 0;  // no JetStream, timeout, no leader...
  std::uint64_t on_demand_requested = 0;  // games asked for by spectators
  std::uint64_t on_demand_found = 0;      // ... that showed up
  std::uint64_t on_demand_unknown = 0;    // ... dropped after the wait
  std::uint64_t on_demand_refused = 0;    // asked for at max_games
  std::uint64_t rejected_subjects = 0;
  struct Game {
    std::string name;
    bool ready = false;      // has its hello
    bool on_demand = false;  // asked for, still waiting
    EdgeSyncStats stats;
  };
  std::vector<Game> games;
};

std::string render_edge_metrics(const EdgeReport& report);

}  // namespace mc::nats
