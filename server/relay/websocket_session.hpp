// One spectator's WebSocket: joins a channel, then sends it frames through a
// bounded queue with one write in flight. Everything queued while a write
// is in flight goes out in the next write, as one gathered write of the
// messages' pre-framed bytes. A slow spectator skips to the next keyframe; a
// stalled one is closed. Nothing a spectator does can slow the channel:
// deliveries only post to this session's thread.
//
// The session runs the WebSocket protocol itself once Beast has parsed the
// upgrade request (server/relay/README.md says why): its writes are the
// queue's batches, its reads go through WsInbound, and pongs and close
// frames are queued like any message, so nothing can interleave.
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
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "server/relay/channel.hpp"
#include "server/relay/connection_limiter.hpp"
#include "server/relay/relay_config.hpp"
#include "server/relay/relay_stats.hpp"
#include "server/relay/replay_source.hpp"
#include "server/relay/send_queue.hpp"
#include "server/relay/session_set.hpp"
#include "server/relay/spectator_link.hpp"
#include "server/relay/ws_inbound.hpp"

namespace mc::relay {

class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
 public:
  // `ticket` holds this client's per-address connection slot for the
  // session's lifetime. `replay`: a private replay of a recording (its
  // channel is `channel`). `timeshift`: opens time shifts of `channel`
  // (nullptr = none). `sessions`: registers itself there while alive.
  WebSocketSession(SpectatorLink&& link, std::shared_ptr<Channel> channel, const RelayConfig& config,
                   RelayStats& stats, std::unique_ptr<ConnectionLimiter::Ticket> ticket,
                   std::shared_ptr<ReplaySource> replay = nullptr, ReplayFactory* timeshift = nullptr,
                   SessionSet* sessions = nullptr);
  ~WebSocketSession();

  // Sends the 101 `handshake_response` (ws_handshake.hpp) and starts the
  // session. `early` holds bytes the client sent right after its request.
  void run(std::string handshake_response, std::string_view early = {});

  // From a channel's publisher thread, through the session's current tap.
  void deliver(std::uint64_t tap_epoch, const Message& m);
  // Graceful stop: a close frame with "going away".
  void shutdown();
  // A close frame with `code` and `reason` (cut to the 123 bytes a close
  // frame holds), e.g. 4404 for a game a NATS edge could not find.
  void close(std::uint16_t code, const std::string& reason);

 private:
  class Tap;
  struct FlushList;
  static thread_local FlushList flush_list_;
  // One write: its messages (which own the bytes) and what is left of its
  // gathered buffers. A write the kernel takes at once, nearly every write
  // on plain TCP, is built in its thread's scratch batch; only a write that
  // must wait (TLS, or a kernel buffer with no room) gets a batch of its own.
  struct WriteBatch;
  static thread_local WriteBatch scratch_;
  void fill(WriteBatch& batch);
  void schedule_flush();

  void start_read();
  void on_readable(boost::system::error_code ec);
  void on_tls_read(boost::system::error_code ec, std::size_t bytes);
  // Takes bytes from the client; false when the session ended on them.
  bool consume(std::string_view bytes);
  void on_text(std::string_view text);
  void on_timeshift(std::string_view action, const double* time);
  // Leaves the current source and joins `channel`: queued messages of the
  // old source are dropped, `announce` and the new one's catch-up (hello,
  // keyframe) queued.
  void switch_to(std::shared_ptr<Channel> channel, std::optional<Message> announce = std::nullopt);
  void enqueue(Message m);
  void write_next();
  void on_writable(boost::system::error_code ec);
  void on_tls_write(boost::system::error_code ec, std::size_t bytes);
  void batch_sent(WriteBatch& batch);
  static void skip_sent(WriteBatch& batch, std::size_t bytes);
  void arm_timer(std::chrono::steady_clock::duration after);
  void on_timer(boost::system::error_code ec);
  void close_with(CloseCode code, std::string_view reason);
  void close_with(std::uint16_t code, std::string_view reason);
  void end_session();     // leaves the channel, stops the replay
  void drop_connection(); // and closes the socket: nothing more in or out
  void account_queue();

  SpectatorLink link_;
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
  SessionSet::Hook in_set_{this};         // this session's place in *sessions_
  std::int64_t accounted_queue_bytes_ = 0;  // this session's share of stats_.queued_bytes
  // Made when the client first sends something: most spectators never do,
  // and then hold no reader at all.
  std::unique_ptr<WsInbound> inbound_;
  std::unique_ptr<char[]> tls_in_;  // TLS only: the decrypted bytes' buffer
  SendQueue queue_;
  // The write waiting for the kernel (or TLS): made for that write, freed
  // when it is out, so that a spectator that keeps up holds no batch at all.
  std::unique_ptr<WriteBatch> pending_;
  std::chrono::steady_clock::time_point write_started_{};
  // Made and armed only while a write waits for the kernel (stall check) or
  // while a close lingers: a healthy spectator has no timer at all.
  std::unique_ptr<boost::asio::steady_timer> timer_;
  // Inbound rate limit: messages in the current one-second window.
  std::chrono::steady_clock::time_point window_start_{};
  int window_messages_ = 0;
  bool writing_ = false;
  bool flush_pending_ = false;  // in this thread's flush list
  bool pong_queued_ = false; // a pong waits in the queue: further pings need no other
  bool open_ = false;        // subscribed: takes messages
  bool shifted_ = false;     // replay_ is a time shift of live_
  bool closing_ = false;     // our close frame is queued or sent
  bool close_sent_ = false;  // and written
  bool peer_closed_ = false; // the client's close frame arrived
  bool dead_ = false;        // the socket is closed
};

}  // namespace mc::relay
