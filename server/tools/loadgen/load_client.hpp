// One simulated spectator: connects to the relay over WebSocket, reads every
// message, checks the frame sequence, measures the delay from the server's
// stamp to receipt, and decodes each frame as a real client would.
// It can also behave badly on purpose: read slowly, or stop reading.
//
// Cheap on purpose, so that one loadgen thread can follow thousands of
// spectators: the upgrade is a Beast HTTP exchange, then the client reads
// whatever the socket holds with one recv and splits it into frames itself
// (ws_frame_parser.hpp), rather than running one Beast read per message.
#pragma once

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "proto/frame_codec.hpp"
#include "server/tools/loadgen/latency_histogram.hpp"

namespace mc::loadgen {

enum class Behaviour { Healthy, Slow, Stalled };

// Counters of all clients of one behaviour on one thread (no locking: each
// thread has its own, merged at the end).
struct ClientStats {
  std::uint64_t connected = 0, failed = 0, closed_by_server = 0;
  std::uint64_t messages = 0, bytes = 0, frames = 0;
  std::uint64_t gaps = 0;            // a seq jump (frames skipped by the relay)
  std::uint64_t frames_skipped = 0;  // sum of the jumps
  std::uint64_t out_of_order = 0;    // seq went backwards or repeated
  std::uint64_t decode_errors = 0;
  // Of the gaps, those that end at a keyframe within 10 s of a "feed"
  // message (lost/back): the resync after the game's feed restarted, which
  // is expected, not a frame the relay failed to deliver.
  std::uint64_t resync_gaps = 0;
  // Stalled clients with a stall_for (soak.hpp): when they read again,
  // whether the relay had cut them off (EOF or reset after what it had
  // sent) or was still sending (a frame stamped after they resumed).
  std::uint64_t stalled_cut = 0, stalled_not_cut = 0;
  // Clients stopped by us while still connecting or upgrading (a burst
  // that left, the end of a run): the relay may have counted the upgrade
  // without the client ever seeing its answer.
  std::uint64_t abandoned = 0;
  std::string first_error;           // the first connect or decode error, for the report
  LatencyHistogram delay;

  void merge(const ClientStats& o);
};

struct ClientOptions {
  boost::asio::ip::tcp::endpoint server;
  boost::asio::ip::address source;  // local address to bind (spreads ports over 127.x)
  std::string host = "127.0.0.1";
  std::string target = "/ws";
  Behaviour behaviour = Behaviour::Healthy;
  std::chrono::milliseconds slow_read_pause{200};  // Slow: pause between reads
  bool decode = true;                               // full decode, or header only
  const SkeletonDef* skeleton = nullptr;            // from the hello
  // Stalled only: read again after this long (0 = never) and find out
  // whether the relay cut the connection meanwhile (ClientStats::stalled_*).
  std::chrono::milliseconds stall_for{0};
};

class LoadClient : public std::enable_shared_from_this<LoadClient> {
 public:
  LoadClient(boost::asio::io_context& ioc, ClientOptions options, ClientStats& stats);
  void start();
  void stop();
  // Connected now; ended: failed, closed, or stopped (soak.hpp replaces
  // the clients that have ended, not those still connecting).
  bool open() const { return open_; }
  bool ended() const { return ended_; }
  // A stalled client that has found out whether it was cut off.
  bool stall_settled() const { return stall_settled_; }

 private:
  void note_failure(const char* step, boost::beast::error_code ec);
  void on_connect(boost::beast::error_code ec);
  void on_request_sent(boost::beast::error_code ec, std::size_t);
  void on_handshake(boost::beast::error_code ec, std::size_t);
  void do_read();
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  // Takes every whole frame in buffer_; false when the connection must end.
  bool take_frames();
  void handle_frame(std::string_view bytes);

  ClientOptions options_;
  ClientStats& stats_;
  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;  // received bytes not yet parsed
  std::unique_ptr<boost::beast::http::request<boost::beast::http::empty_body>> request_;
  std::unique_ptr<boost::beast::http::response<boost::beast::http::string_body>> response_;
  boost::asio::steady_timer pause_;
  std::unique_ptr<proto::FrameDecoder> decoder_;
  PoseFrame frame_;
  std::uint64_t connected_at_ms_ = 0;
  double last_feed_message_ms_ = -1e18;  // a "feed" lost/back message, for resync_gaps
  double resumed_at_ms_ = 0;             // a stalled client reading again
  bool draining_ = false, stall_settled_ = false, ended_ = false;
  std::uint32_t last_seq_ = 0;
  bool have_seq_ = false;
  bool open_ = false;
};

// Unix time in ms with sub-ms precision, the clock the server stamps with.
double unix_ms_now();

}  // namespace mc::loadgen
