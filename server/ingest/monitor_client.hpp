// The live feed: a UDP monitor client like rcssmonitor's, as a StateSource.
//
// Handshake (rcss-protocol.md section 2): send "(dispinit version N)\0" to
// the server port; the server answers from a new per-monitor port, whose
// number we remember and send later commands to. The client is driven from
// the caller's thread (no thread of its own): next()/next_for() receive,
// decode (MonitorStream) and manage the connection:
//   - no datagram for `lost_after` -> FeedLost event, then re-handshake
//     with exponential backoff (server gone or restarted);
//   - the first datagram after that -> FeedBack event (also sent once at
//     the first connection, detail "connected").
// Parameters and player types are taken from the feed whenever sent.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "server/ingest/monitor_stream.hpp"
#include "server/ingest/udp_socket.hpp"

namespace mc::ingest {

struct MonitorClientConfig {
  std::string host = "127.0.0.1";  // rcssserver's host
  std::uint16_t port = 6000;       // server::port, where monitors send (dispinit)
  // Protocol: 5 (rcssmonitor's default, richest text), 4, 3, or -1 (JSON);
  // 1 and 2 (binary) are accepted too.
  int version = 5;
  // rcssmonitor treats 5 s without data as a lost connection.
  std::chrono::milliseconds lost_after{5000};
  // Re-handshake interval: starts here, doubles up to backoff_max.
  std::chrono::milliseconds backoff_initial{500};
  std::chrono::milliseconds backoff_max{8000};
};

class MonitorClient final : public StateSource {
 public:
  // Opens the local socket (ephemeral port). If that fails, error() says why
  // and next() returns false at once.
  explicit MonitorClient(MonitorClientConfig config);
  ~MonitorClient() override;  // sends (dispbye) when connected

  // Blocks until a state arrives; false only after stop() or if the socket
  // could not be opened. During an outage it keeps retrying (use next_for()
  // to get control back and drain FeedLost/FeedBack events).
  bool next(WorldState& out) override;
  Wait next_for(WorldState& out, std::chrono::milliseconds timeout) override;
  const GameParams& params() const override { return stream_.params(); }
  const IngestStats& stats() const override { return stream_.stats(); }
  bool poll_event(SourceEvent& out) override { return stream_.poll_event(out); }

  // Thread-safe: makes a blocked next() return false within ~50 ms.
  void stop() override { stopping_ = true; }
  bool connected() const { return connected_; }
  // The server's per-monitor port (0 before the first reply).
  std::uint16_t server_port() const { return server_.port; }
  // Sends a command, e.g. "(dispstart)", to the per-monitor port. False when
  // not connected or the send failed.
  bool send_command(std::string_view command);
  const std::string& error() const { return error_; }

 private:
  void send_dispinit();
  void on_datagram(std::size_t size, const UdpEndpoint& from, WorldState& out, bool& got_state);
  void check_timers();

  using Clock = std::chrono::steady_clock;
  MonitorClientConfig config_;
  UdpSocket socket_;
  UdpEndpoint init_addr_;  // host:port for (dispinit)
  UdpEndpoint server_;     // host:per-monitor port once connected
  MonitorStream stream_;
  std::vector<char> buf_;
  bool resolved_ = false;
  bool connected_ = false;
  bool ever_connected_ = false;
  Clock::time_point last_rx_{};
  Clock::time_point next_init_{};
  std::chrono::milliseconds backoff_;
  std::atomic<bool> stopping_{false};
  std::string error_;
};

}  // namespace mc::ingest
