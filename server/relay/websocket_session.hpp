// One spectator's WebSocket: joins a channel, then sends it frames through a
// bounded queue with one write in flight. A slow spectator skips to the next
// keyframe; a stalled one is closed. Nothing a spectator does can slow the
// channel: deliver() only posts to this session's strand.
#pragma once

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <memory>
#include <vector>

#include "server/relay/channel.hpp"
#include "server/relay/connection_limiter.hpp"
#include "server/relay/relay_config.hpp"
#include "server/relay/relay_stats.hpp"
#include "server/relay/replay_source.hpp"
#include "server/relay/send_queue.hpp"

namespace mc::relay {

class WebSocketSession : public Subscriber,
                         public std::enable_shared_from_this<WebSocketSession> {
 public:
  // `ticket` holds this client's per-address connection slot for the
  // session's lifetime.
  WebSocketSession(boost::beast::tcp_stream&& stream, std::shared_ptr<Channel> channel,
                   const RelayConfig& config, RelayStats& stats,
                   std::unique_ptr<ConnectionLimiter::Ticket> ticket,
                   std::shared_ptr<ReplaySource> replay = nullptr);
  ~WebSocketSession() override;

  // Completes the upgrade for `req` and starts the session.
  void run(boost::beast::http::request<boost::beast::http::string_body> req);

  // Subscriber: called from the publisher's thread.
  void deliver(const Message& m) override;
  // Graceful stop: a close frame with "going away".
  void shutdown() override;

 private:
  void on_accept(boost::beast::error_code ec);
  void do_read();
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  void enqueue(Message m);
  void write_next();
  void on_write(boost::beast::error_code ec, std::size_t bytes);
  void on_stall_timer(boost::beast::error_code ec);
  void close_with(boost::beast::websocket::close_code code, const char* reason);
  void end_session();
  void account_queue();

  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  std::shared_ptr<Channel> channel_;
  const RelayConfig& config_;
  RelayStats& stats_;
  std::unique_ptr<ConnectionLimiter::Ticket> ticket_;
  std::shared_ptr<ReplaySource> replay_;  // set for a private replay: gets the spectator's messages
  std::int64_t accounted_queue_bytes_ = 0;  // this session's share of stats_.queued_bytes
  boost::beast::flat_buffer in_;
  SendQueue queue_;
  std::vector<Message> batch_;  // the write in flight and the rest of its batch
  std::size_t batch_pos_ = 0;
  bool writing_ = false;
  bool open_ = false;
  bool closing_ = false;
  boost::asio::steady_timer stall_timer_;
  // Inbound rate limit: messages in the current one-second window.
  std::chrono::steady_clock::time_point window_start_{};
  int window_messages_ = 0;
};

}  // namespace mc::relay
