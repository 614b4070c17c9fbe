// One spectator's WebSocket: joins a channel, then sends it frames through a
// bounded queue with one write in flight. Everything queued while a write
// is in flight goes out in the next write, as one gathered write of the
// messages' pre-framed bytes (see transport.hpp). A slow spectator skips to
// the next keyframe; a stalled one is closed. Nothing a spectator does can
// slow the channel: deliveries only post to this session's strand.
//
// Time shift: a live spectator may rewind its channel without leaving it.
// The session then follows a private replay of the channel's running
// recording, and comes back to the live feed (at its latest keyframe) on
// request. Spectator -> server, text JSON:
//   {"type":"timeshift","action":"seek","time":CYCLE}   rewind (or move) to CYCLE
//   {"type":"timeshift","action":"live"}                back to the live feed
//   {"type":"replay",...}                               while shifted: pause, speed, goals...
// Server -> spectator: {"type":"timeshift","mode":"replay"|"live"} on each
// switch (or with "error" when the channel has no recording), then the new
// stream's hello and keyframe; while shifted, the replay's status messages.
#pragma once

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "server/relay/channel.hpp"
#include "server/relay/connection_limiter.hpp"
#include "server/relay/relay_config.hpp"
#include "server/relay/relay_stats.hpp"
#include "server/relay/replay_source.hpp"
#include "server/relay/send_queue.hpp"
#include "server/relay/session_set.hpp"
#include "server/relay/transport.hpp"

namespace mc::relay {

class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
 public:
  // `ticket` holds this client's per-address connection slot for the
  // session's lifetime. `replay`: a private replay of a recording (its
  // channel is `channel`). `timeshift`: opens time shifts of `channel`
  // (nullptr = none). `sessions`: registers itself there while alive.
  WebSocketSession(Transport&& transport, std::shared_ptr<Channel> channel, const RelayConfig& config,
                   RelayStats& stats, std::unique_ptr<ConnectionLimiter::Ticket> ticket,
                   std::shared_ptr<ReplaySource> replay = nullptr, ReplayFactory* timeshift = nullptr,
                   SessionSet* sessions = nullptr);
  ~WebSocketSession();

  // Completes the upgrade for `req` and starts the session.
  void run(boost::beast::http::request<boost::beast::http::string_body> req);

  // From a channel's publisher thread, through the session's current tap.
  void deliver(std::uint64_t tap_epoch, const Message& m);
  // Graceful stop: a close frame with "going away".
  void shutdown();
  // A close frame with `code` and `reason` (cut to the 123 bytes a close
  // frame holds), e.g. 4404 for a game a NATS edge could not find.
  void close(std::uint16_t code, const std::string& reason);

 private:
  class Tap;

  void on_accept(boost::beast::error_code ec);
  void do_read();
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  void on_text(std::string_view text);
  void on_timeshift(std::string_view action, const double* time);
  // Leaves the current source and joins `channel`: queued messages of the
  // old source are dropped, `announce` and the new one's catch-up (hello,
  // keyframe) queued.
  void switch_to(std::shared_ptr<Channel> channel, std::optional<Message> announce = std::nullopt);
  void enqueue(Message m);
  void write_next();
  void on_write(boost::beast::error_code ec, std::size_t bytes);
  void batch_sent(std::size_t bytes);
  void arm_stall_check();
  void on_stall_check(boost::beast::error_code ec);
  void close_with(boost::beast::websocket::close_code code, std::string_view reason);
  void end_session();
  void account_queue();

  boost::beast::websocket::stream<Transport> ws_;
  std::shared_ptr<Channel> live_;     // the channel the spectator asked for
  std::shared_ptr<Channel> current_;  // the one it follows now
  std::shared_ptr<Tap> tap_;          // current_'s subscription
  std::uint64_t epoch_ = 0;           // tap_'s number; older taps' deliveries are stale
  const RelayConfig& config_;
  RelayStats& stats_;
  std::unique_ptr<ConnectionLimiter::Ticket> ticket_;
  std::shared_ptr<ReplaySource> replay_;  // a recording's replay, or the current time shift
  ReplayFactory* timeshift_factory_;
  SessionSet* sessions_;                  // for a graceful stop; may be nullptr
  bool shifted_ = false;                  // replay_ is a time shift of live_
  std::int64_t accounted_queue_bytes_ = 0;  // this session's share of stats_.queued_bytes
  boost::beast::flat_buffer in_;
  SendQueue queue_;
  std::vector<Message> batch_;  // the write in flight: owns the bytes of...
  std::vector<boost::asio::const_buffer> buffers_;  // ...its gathered buffers
  std::size_t sent_inline_ = 0;  // bytes of the batch in flight written before it went asynchronous
  std::chrono::steady_clock::time_point write_started_{};
  bool writing_ = false;
  bool open_ = false;
  bool closing_ = false;
  boost::asio::steady_timer stall_timer_;  // a periodic check, not one timer per write
  // Inbound rate limit: messages in the current one-second window.
  std::chrono::steady_clock::time_point window_start_{};
  int window_messages_ = 0;
};

}  // namespace mc::relay
