#include "server/relay/websocket_session.hpp"

#include <boost/asio/bind_executor.hpp>
#include <boost/asio/post.hpp>

#include "server/relay/log.hpp"

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace net = boost::asio;

namespace mc::relay {
namespace {
// Spectators only ever send small control messages; more than this per
// second is a broken or hostile client.
constexpr int kMaxInboundPerSecond = 20;
}  // namespace

WebSocketSession::WebSocketSession(beast::tcp_stream&& stream, std::shared_ptr<Channel> channel,
                                   const RelayConfig& config, RelayStats& stats,
                                   std::unique_ptr<ConnectionLimiter::Ticket> ticket,
                                   std::shared_ptr<ReplaySource> replay)
    : ws_(std::move(stream)),
      channel_(std::move(channel)),
      config_(config),
      stats_(stats),
      ticket_(std::move(ticket)),
      replay_(std::move(replay)),
      queue_(config.max_queue_bytes),
      stall_timer_(ws_.get_executor()) {
  ++stats_.clients;
  ++stats_.connections_total;
}

WebSocketSession::~WebSocketSession() {
  --stats_.clients;
  stats_.queued_bytes -= accounted_queue_bytes_;
  stats_.frames_dropped += queue_.dropped();
}

void WebSocketSession::account_queue() {
  const auto now = static_cast<std::int64_t>(queue_.bytes());
  stats_.queued_bytes += now - accounted_queue_bytes_;
  accounted_queue_bytes_ = now;
}

void WebSocketSession::end_session() {
  open_ = false;
  channel_->leave(this);
  stall_timer_.cancel();
  if (replay_) {
    replay_->close();
    replay_.reset();
  }
}

void WebSocketSession::shutdown() {
  net::post(ws_.get_executor(), [self = shared_from_this()] {
    self->close_with(websocket::close_code::going_away, "server shutting down");
  });
}

void WebSocketSession::run(beast::http::request<beast::http::string_body> req) {
  beast::get_lowest_layer(ws_).expires_never();
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.read_message_max(config_.max_inbound_message);
  ws_.set_option(websocket::stream_base::decorator([](websocket::response_type& res) {
    res.set(beast::http::field::server, "matchcast");
  }));
  ws_.async_accept(req, beast::bind_front_handler(&WebSocketSession::on_accept, shared_from_this()));
}

void WebSocketSession::on_accept(beast::error_code ec) {
  if (ec) return log_event("ws_accept_failed", ec.message());
  open_ = true;
  // Join and queue the catch-up on this strand, before any later deliver()
  // (which is posted to the same strand) can run: nothing is missed or doubled.
  for (auto& m : channel_->join(shared_from_this())) enqueue(std::move(m));
  do_read();
}

void WebSocketSession::do_read() {
  ws_.async_read(in_, beast::bind_front_handler(&WebSocketSession::on_read, shared_from_this()));
}

void WebSocketSession::on_read(beast::error_code ec, std::size_t) {
  if (ec) {
    // Closed by the peer, timed out, or a protocol violation (including a
    // message over read_message_max): the session ends.
    if (ec == websocket::error::message_too_big) ++stats_.inbound_rejected;
    end_session();
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (now - window_start_ > std::chrono::seconds(1)) {
    window_start_ = now;
    window_messages_ = 0;
  }
  if (++window_messages_ > kMaxInboundPerSecond) {
    in_.consume(in_.size());
    ++stats_.inbound_rejected;
    return close_with(websocket::close_code::policy_error, "too many messages");
  }
  // Live spectators are read-only: their messages are ignored. A replay's
  // spectator steers its own replay.
  if (replay_ && ws_.got_text()) {
    const auto data = in_.data();
    replay_->on_client_message({static_cast<const char*>(data.data()), data.size()});
  }
  in_.consume(in_.size());
  do_read();
}

void WebSocketSession::deliver(const Message& m) {
  net::post(ws_.get_executor(), [self = shared_from_this(), m] { self->enqueue(m); });
}

void WebSocketSession::enqueue(Message m) {
  if (!open_ || closing_) return;
  queue_.push(std::move(m));
  account_queue();
  if (!writing_) write_next();
}

void WebSocketSession::write_next() {
  if (closing_ || !open_) {
    // A close frame is queued behind the write that just ended, or the
    // session is over: nothing more goes out.
    writing_ = false;
    stall_timer_.cancel();
    return;
  }
  if (batch_pos_ >= batch_.size()) {
    batch_.clear();
    batch_pos_ = 0;
    // Everything that queued during the last write goes out as one batch.
    queue_.take_all(batch_);
    account_queue();
    if (batch_.empty()) {
      writing_ = false;
      stall_timer_.cancel();
      return;
    }
  }
  writing_ = true;
  const Message& m = batch_[batch_pos_];
  ws_.binary(m.binary());
  stall_timer_.expires_after(config_.stall_timeout);
  stall_timer_.async_wait(
      beast::bind_front_handler(&WebSocketSession::on_stall_timer, shared_from_this()));
  ws_.async_write(net::buffer(*m.bytes),
                  beast::bind_front_handler(&WebSocketSession::on_write, shared_from_this()));
}

void WebSocketSession::on_write(beast::error_code ec, std::size_t bytes) {
  if (ec) {
    writing_ = false;
    end_session();
    return;
  }
  ++stats_.messages_sent;
  stats_.bytes_sent += bytes;
  const Message& sent = batch_[batch_pos_];
  if (sent.binary())
    stats_.record_delay(std::chrono::duration<double, std::milli>(
                            std::chrono::steady_clock::now() - sent.published)
                            .count());
  ++batch_pos_;
  write_next();
}

void WebSocketSession::on_stall_timer(beast::error_code ec) {
  if (ec == net::error::operation_aborted || !writing_) return;
  // One write has not completed for stall_timeout: the client stopped
  // reading. Its kernel buffer is full, so a close frame cannot reach it
  // either; drop the connection and free its queue.
  ++stats_.closed_slow;
  log_event("ws_closed_stalled", channel_->name());
  end_session();
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().close(ignored);
}

void WebSocketSession::close_with(websocket::close_code code, const char* reason) {
  if (closing_ || !open_) return;
  closing_ = true;
  end_session();
  ws_.async_close(websocket::close_reason(code, reason),
                  [self = shared_from_this()](beast::error_code) {});
}

}  // namespace mc::relay
