// matchcast-feeder: replays any game log as if it were a live rcssserver
// monitor port, so the live path can be tested (and demoed) without
// rcssserver. It behaves like the server towards monitors
// (rcss-protocol.md section 2): a monitor sends "(dispinit version N)" to
// the feeder's port; the feeder answers from a new per-monitor socket with
// server_param, player_param and the player types, then one show (with
// (pm)/(tm)) every simulator step, plus the log's (msg ..) records.
// Versions 1, 2 (binary), 3, 4, 5 (text) and -1 (JSON) are served; others
// get "(error illegal_client_version)" like rcssserver would.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "server/ingest/state_source.hpp"
#include "server/ingest/udp_socket.hpp"

namespace mc::feeder {

struct FeederConfig {
  std::string log_path;             // any .rcg / .rcg.gz open_log() reads
  std::string bind_host = "127.0.0.1";
  std::uint16_t port = 6000;        // rcssserver's default; 0 = ephemeral
  double speed = 1.0;               // 2 = twice real time
  bool loop = false;                // start over at the end of the log
  // Start the replay when the first monitor connects, so it sees the game
  // from its first show (rcssserver likewise waits in before_kick_off).
  bool wait_for_monitor = true;
  std::chrono::milliseconds step{100};  // simulator_step
  std::size_t max_monitors = 16;        // more get "(error no_more_monitor)"
};

class Feeder {
 public:
  explicit Feeder(FeederConfig config);
  // Binds the port and opens the log (reads its first show, so parameters
  // are known). False + error on failure.
  bool open(std::string& error);
  // The bound port (after open(); useful with port 0).
  std::uint16_t port() const { return main_.local_port(); }
  // Serves until stop(), or until the log ends when not looping. False +
  // error on a fatal socket or log error.
  bool run(std::string& error);
  // Thread-safe; run() returns within ~50 ms.
  void stop() { stopping_ = true; }

  std::uint64_t shows_sent() const { return shows_sent_; }  // shows ticked (to all monitors)
  std::size_t monitors() const { return monitor_count_; }

 private:
  struct Monitor {
    ingest::UdpEndpoint addr;
    ingest::UdpSocket socket;  // per-monitor port, connected to addr
    int version = 5;
  };
  bool open_log(std::string& error);
  bool advance(std::string& error);  // reads the next state (loops if asked)
  void on_init_port();
  void on_monitor(std::size_t i);
  void accept_monitor(const ingest::UdpEndpoint& from, int version);
  void tick();
  void send_to(Monitor& m, std::string_view payload);

  FeederConfig config_;
  ingest::UdpSocket main_;
  std::unique_ptr<ingest::StateSource> log_;
  WorldState pending_;          // the next show to send
  bool have_pending_ = false;
  std::vector<ingest::SourceEvent> pending_events_;  // msgs before pending_
  std::vector<std::unique_ptr<Monitor>> monitors_;
  std::vector<char> buf_;
  std::atomic<bool> stopping_{false};
  std::atomic<std::uint64_t> shows_sent_{0};
  std::atomic<std::size_t> monitor_count_{0};
};

// Parses "(dispinit)" -> 1, "(dispinit version N)" -> N (as rcssserver's
// sscanf does, the number may be real and is truncated). False if `text` is
// not a dispinit.
bool parse_dispinit(std::string_view text, int& version);

}  // namespace mc::feeder
