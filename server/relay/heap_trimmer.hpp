// Gives the heap's free pages back to the system after connections come and
// go. Each connection's HTTP request (Beast's parser, its header fields, the
// read buffer, tcp_stream's timers) is freed at the upgrade, between the
// long-lived sessions allocated around it: glibc keeps those holes, and
// the RSS with them (~0.4 KB per spectator measured after 1,000 joins).
// malloc_trim(0) returns every whole free page, holes included; it walks
// the heap, so it runs at most once a period, on one I/O thread: when a
// burst of connections (opened or closed) has ended, or during a long one
// once enough connections have come and gone.
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
  // While connections keep coming and going, a trim waits for this many
  // since the last one.
  static constexpr std::uint64_t kMinChurn = 256;
  static constexpr std::chrono::seconds kPeriod{5};

  HeapTrimmer(boost::asio::io_context& ioc, const RelayStats& stats) : timer_(ioc), stats_(stats) {}
  // Trims once at once: what start-up freed (options, the log's first
  // reads, the feeds' set-up) goes back before the first spectator, so that
  // later trims return what spectators leave, and the RSS growth that the
  // fan-out benchmark divides by the spectators is theirs alone.
  void start() {
    trim();
    arm();
  }
  void stop();  // from any thread

  // Connections opened plus connections closed so far.
  static std::uint64_t churn(const RelayStats& stats);
  // Returns free heap pages to the system now; false when there is no such
  // call (not glibc).
  static bool trim();

 private:
  void arm();

  boost::asio::steady_timer timer_;
  const RelayStats& stats_;
  std::uint64_t churn_at_last_trim_ = 0;
  std::uint64_t churn_at_last_tick_ = 0;
};

}  // namespace mc::relay
