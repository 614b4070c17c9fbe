// Gives the heap's free pages back to the system after connections come and
// go. Each connection's HTTP request (Beast's parser, its header fields, the
// read buffer, tcp_stream's timers) is freed at the upgrade, between the
// long-lived sessions allocated around it: glibc keeps those holes, and
// the RSS with them (~0.4 KB per spectator measured after 1,000 joins).
// malloc_trim(0) returns every whole free page, holes included. It runs on
// one I/O thread once a second when connections have come or gone since
// the last trim: with a steady churn (the soak's 20 joins and 20 leaves a
// second) trims 5-10 s apart left a saw-tooth of ~300 KB on a 14 MB
// process, larger than the 2 % an operator reads as "flat". Its cost is in
// /metrics (matchcast_heap_trim_seconds_total).
#pragma once

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <cstdint>
#include <memory>

#include "server/relay/relay_stats.hpp"

namespace mc::relay {

class HeapTrimmer : public std::enable_shared_from_this<HeapTrimmer> {
 public:
  static constexpr std::chrono::seconds kPeriod{1};

  HeapTrimmer(boost::asio::io_context& ioc, RelayStats& stats) : timer_(ioc), stats_(stats) {
    set_allocator_policy();
  }
  // Trims once at once: what start-up freed (options, the log's first
  // reads, the feeds' set-up) goes back before the first spectator, so that
  // later trims return what spectators leave, and the RSS growth that the
  // fan-out benchmark divides by the spectators is theirs alone.
  void start() {
    trim_now();
    arm();
  }
  void stop();  // from any thread

  // The process's allocator policy, set once (the first HeapTrimmer sets
  // it): blocks of 64 KB and more are mapped on their own and unmapped when
  // freed, at a fixed threshold. glibc's default threshold moves up each
  // time such a block is freed, so that after the first feed restart or
  // replay the 64-128 KB blocks (a frame encoder's partner table, a log's
  // read window, a recording's chunk) land inside the heap, between small
  // long-lived ones, where their pages stay resident after they are freed.
  // Side by side in 10-minute soaks (2,000 spectators, a burst every 100
  // s): RSS spread at the steady points 3.94 % with glibc's default, 2.19 %
  // with this. Returns false when there is no such call (not glibc).
  static bool set_allocator_policy();
  static constexpr int kMmapThreshold = 64 * 1024;

  // Connections opened plus connections closed so far.
  static std::uint64_t churn(const RelayStats& stats);
  // Returns free heap pages to the system now; false when there is no such
  // call (not glibc).
  static bool trim();

 private:
  void arm();
  void trim_now();  // trim(), timed into the stats

  boost::asio::steady_timer timer_;
  RelayStats& stats_;
  std::uint64_t churn_at_last_trim_ = 0;
};

}  // namespace mc::relay
