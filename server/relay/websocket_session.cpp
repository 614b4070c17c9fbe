#include "server/relay/websocket_session.hpp"

#include <boost/asio/post.hpp>
#include <nlohmann/json.hpp>

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

// A session's subscription to one channel. A new tap per switch: deliveries
// from a channel the session has left carry an old epoch and are ignored.
class WebSocketSession::Tap : public Subscriber {
 public:
  Tap(std::weak_ptr<WebSocketSession> session, std::uint64_t epoch, net::io_context* home)
      : session_(std::move(session)), epoch_(epoch), home_(home) {}
  void deliver(const Message& m) override {
    if (auto s = session_.lock()) s->deliver(epoch_, m);
  }
  net::io_context* home() override { return home_; }
  // On the session's own thread: straight into its queue.
  void deliver_here(const Message& m) override {
    if (auto s = session_.lock())
      if (s->epoch_ == epoch_) s->enqueue(m);
  }
  void shutdown() override {
    if (auto s = session_.lock()) s->shutdown();
  }
  void close(std::uint16_t code, const std::string& reason) override {
    if (auto s = session_.lock()) s->close(code, reason);
  }

 private:
  std::weak_ptr<WebSocketSession> session_;
  std::uint64_t epoch_;
  net::io_context* home_;
};

WebSocketSession::WebSocketSession(Transport&& transport, std::shared_ptr<Channel> channel,
                                   const RelayConfig& config, RelayStats& stats,
                                   std::unique_ptr<ConnectionLimiter::Ticket> ticket,
                                   std::shared_ptr<ReplaySource> replay, ReplayFactory* timeshift,
                                   SessionSet* sessions)
    : ws_(std::move(transport)),
      live_(std::move(channel)),
      config_(config),
      stats_(stats),
      ticket_(std::move(ticket)),
      replay_(std::move(replay)),
      timeshift_factory_(replay_ ? nullptr : timeshift),
      sessions_(sessions),
      queue_(config.max_queue_bytes),
      stall_timer_(ws_.get_executor()) {
  ++stats_.clients;
  ++stats_.connections_total;
}

WebSocketSession::~WebSocketSession() {
  if (sessions_) sessions_->remove(this);
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
  if (current_ && tap_) current_->leave(tap_.get());
  tap_.reset();
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

void WebSocketSession::close(std::uint16_t code, const std::string& reason) {
  net::post(ws_.get_executor(), [self = shared_from_this(), code, reason] {
    self->close_with(static_cast<websocket::close_code>(code), reason);
  });
}

void WebSocketSession::run(beast::http::request<beast::http::string_body> req) {
  if (sessions_) sessions_->add(shared_from_this());
  auto& transport = ws_.next_layer();
  transport.set_owner(weak_from_this());
  transport.on_idle([this] {
    if (!writing_) write_next();
  });
  transport.tcp().expires_never();
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
  switch_to(live_);
  arm_stall_check();
  do_read();
}

void WebSocketSession::switch_to(std::shared_ptr<Channel> channel, std::optional<Message> announce) {
  if (current_ && tap_) current_->leave(tap_.get());
  // A session on a thread of its own (the relay's io_context per thread)
  // is served by its channel's per-thread task; otherwise by posts.
  auto executor = ws_.get_executor();
  auto* on_thread = executor.target<net::io_context::executor_type>();
  tap_ = std::make_shared<Tap>(weak_from_this(), ++epoch_, on_thread ? &on_thread->context() : nullptr);
  current_ = std::move(channel);
  std::vector<Message> dropped;
  queue_.take_all(dropped);  // the old source's backlog is of no use now
  if (announce) enqueue(std::move(*announce));
  for (auto& m : current_->join(tap_)) enqueue(std::move(m));
  account_queue();
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
  if (ws_.got_text()) {
    const auto data = in_.data();
    on_text({static_cast<const char*>(data.data()), data.size()});
  }
  in_.consume(in_.size());
  if (open_) do_read();
}

void WebSocketSession::on_text(std::string_view text) {
  // A recording's replay gets every message of its spectator.
  if (replay_ && !shifted_) return replay_->on_client_message(text);
  if (!timeshift_factory_) return;  // live spectators are otherwise read-only
  const auto j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || !j.contains("type") || !j["type"].is_string()) return;
  const std::string& type = j["type"].get_ref<const std::string&>();
  if (type == "replay" && shifted_) return replay_->on_client_message(text);
  if (type != "timeshift" || !j.contains("action") || !j["action"].is_string()) return;
  double time = 0;
  const bool has_time = j.contains("time") && j["time"].is_number();
  if (has_time) time = j["time"].get<double>();
  on_timeshift(j["action"].get_ref<const std::string&>(), has_time ? &time : nullptr);
}

void WebSocketSession::on_timeshift(std::string_view action, const double* time) {
  if (action == "seek" && time) {
    if (!shifted_) {
      std::string error;
      auto replay = timeshift_factory_->open_timeshift(live_->name(), ws_.get_executor(), error);
      if (!replay) {
        enqueue(Message::control(nlohmann::json{{"type", "timeshift"}, {"mode", "live"}, {"error", error}}.dump(
            -1, ' ', false, nlohmann::json::error_handler_t::replace)));
        return;
      }
      replay_ = std::move(replay);
      shifted_ = true;
      switch_to(replay_->channel(), Message::control(R"({"type":"timeshift","mode":"replay"})"));
      log_event("timeshift", live_->name());
    }
    replay_->on_client_message(
        nlohmann::json{{"type", "replay"}, {"action", "seek"}, {"time", *time}}.dump());
  } else if (action == "live" && shifted_) {
    replay_->close();
    replay_.reset();
    shifted_ = false;
    switch_to(live_, Message::control(R"({"type":"timeshift","mode":"live"})"));
  }
}

void WebSocketSession::deliver(std::uint64_t tap_epoch, const Message& m) {
  net::post(ws_.get_executor(), [self = shared_from_this(), tap_epoch, m] {
    if (tap_epoch == self->epoch_) self->enqueue(m);
  });
}

void WebSocketSession::enqueue(Message m) {
  if (!open_ || closing_) return;
  queue_.push(std::move(m));
  account_queue();
  if (!writing_) write_next();
}

void WebSocketSession::write_next() {
  // A loop, not recursion: each batch the kernel takes at once is followed
  // by whatever queued meanwhile.
  for (;;) {
    writing_ = false;
    // A close frame is queued behind the write that just ended, or the
    // session is over: nothing more goes out. Or Beast is writing a control
    // frame (pong, close): the transport calls back when it is done.
    if (closing_ || !open_ || !ws_.next_layer().can_write_raw() || queue_.empty()) return;
    // Everything that queued during the last write goes out as one batch.
    batch_.clear();
    buffers_.clear();
    queue_.take_all(batch_);
    account_queue();
    std::size_t total = 0;
    for (const auto& m : batch_) {
      buffers_.push_back(net::buffer(*m.wire));
      total += m.wire->size();
    }
    writing_ = true;
    write_started_ = std::chrono::steady_clock::now();
    ++stats_.writes;
    sent_inline_ = 0;
    if (!ws_.next_layer().is_tls()) {
      beast::error_code ec;
      sent_inline_ = ws_.next_layer().try_write_raw(buffers_, ec);
      if (ec && ec != net::error::would_block) {
        writing_ = false;
        end_session();
        return;
      }
      if (sent_inline_ == total) {
        batch_sent(total);
        continue;
      }
      // The kernel took part: the rest waits for room, asynchronously.
      ++stats_.partial_writes;
      std::size_t skip = sent_inline_;
      auto first = buffers_.begin();
      while (skip >= first->size()) skip -= (first++)->size();
      *first += skip;
      buffers_.erase(buffers_.begin(), first);
    }
    ws_.next_layer().async_write_raw(
        buffers_, beast::bind_front_handler(&WebSocketSession::on_write, shared_from_this()));
    return;
  }
}

void WebSocketSession::on_write(beast::error_code ec, std::size_t bytes) {
  writing_ = false;
  if (ec) {
    end_session();
    return;
  }
  batch_sent(sent_inline_ + bytes);
  write_next();
}

void WebSocketSession::batch_sent(std::size_t bytes) {
  stats_.messages_sent += batch_.size();
  stats_.bytes_sent += bytes;
  const auto now = std::chrono::steady_clock::now();
  for (const auto& sent : batch_)
    if (sent.binary())
      stats_.record_delay(std::chrono::duration<double, std::milli>(now - sent.published).count());
}

void WebSocketSession::arm_stall_check() {
  // Checked a few times per stall timeout: bounds detection to 1.25x the
  // timeout without arming a timer for every write.
  stall_timer_.expires_after(std::max(config_.stall_timeout / 4, std::chrono::milliseconds(10)));
  stall_timer_.async_wait(beast::bind_front_handler(&WebSocketSession::on_stall_check, shared_from_this()));
}

void WebSocketSession::on_stall_check(beast::error_code ec) {
  if (ec == net::error::operation_aborted || !open_) return;
  if (!writing_ || std::chrono::steady_clock::now() - write_started_ < config_.stall_timeout)
    return arm_stall_check();
  // One write has not completed for stall_timeout: the client stopped
  // reading. Its kernel buffer is full, so a close frame cannot reach it
  // either; drop the connection and free its queue.
  ++stats_.closed_slow;
  log_event("ws_closed_stalled", live_->name());
  end_session();
  ws_.next_layer().close();
}

void WebSocketSession::close_with(websocket::close_code code, std::string_view reason) {
  if (closing_ || !open_) return;
  closing_ = true;
  end_session();
  constexpr std::size_t kMaxReason = 123;  // RFC 6455: 125-byte payload, 2 of them the code
  reason = reason.substr(0, kMaxReason);
  ws_.async_close(websocket::close_reason(code, beast::string_view(reason.data(), reason.size())),
                  [self = shared_from_this()](beast::error_code) {});
}

}  // namespace mc::relay
