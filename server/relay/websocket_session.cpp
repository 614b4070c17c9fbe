#include "server/relay/websocket_session.hpp"

#include <boost/asio/post.hpp>
#include <iterator>
#include <nlohmann/json.hpp>

#include "server/relay/log.hpp"
#include "server/relay/spectator_message.hpp"

namespace net = boost::asio;
using boost::system::error_code;

namespace mc::relay {
namespace {
// Spectators only ever send small control messages; more than this per
// second is a broken or hostile client.
constexpr int kMaxInboundPerSecond = 20;
// After our close frame, how long the client has to answer before the
// socket is closed anyway.
constexpr auto kCloseLinger = std::chrono::seconds(2);
// Plain TCP reads go through one buffer per I/O thread: a spectator that
// sent nothing (nearly all of them) holds none.
constexpr std::size_t kReadChunk = 16 * 1024;
// TLS records are at most 16 KB; one read takes what one record holds.
constexpr std::size_t kTlsReadBuffer = 16 * 1024;
}  // namespace

// Sessions of this I/O thread that have messages queued and no write in
// flight. They are written together by one task at the end of the loop
// turn, so messages published back to back (a kick, a stamina update, a
// director cue and the frame) leave in one write per spectator, not one
// each. Valid because every session's io_context runs on one thread.
struct WebSocketSession::FlushList {
  std::vector<std::shared_ptr<WebSocketSession>> sessions;
  bool posted = false;
};
thread_local WebSocketSession::FlushList WebSocketSession::flush_list_;

void WebSocketSession::schedule_flush() {
  flush_pending_ = true;
  flush_list_.sessions.push_back(shared_from_this());
  if (flush_list_.posted) return;
  flush_list_.posted = true;
  net::post(link_.get_executor(), [] {
    auto sessions = std::move(flush_list_.sessions);
    flush_list_.sessions.clear();
    flush_list_.posted = false;
    for (auto& s : sessions) {
      s->flush_pending_ = false;
      if (!s->writing_) s->write_next();
    }
    // Keep the vector's room for the next turn.
    sessions.clear();
    if (flush_list_.sessions.empty()) flush_list_.sessions.swap(sessions);
  });
}

struct WebSocketSession::WriteBatch {
  std::vector<Message> messages;
  std::vector<net::const_buffer> buffers;
  std::size_t bytes = 0;  // the whole batch, sent or not
  void clear() {
    messages.clear();
    buffers.clear();
    bytes = 0;
  }
};
// Used only from filling a batch to the end of its non-blocking write, with
// no handler run in between: one per thread serves all its sessions.
thread_local WebSocketSession::WriteBatch WebSocketSession::scratch_;

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

WebSocketSession::WebSocketSession(SpectatorLink&& link, std::shared_ptr<Channel> channel,
                                   const RelayConfig& config, RelayStats& stats,
                                   std::unique_ptr<ConnectionLimiter::Ticket> ticket,
                                   std::shared_ptr<ReplaySource> replay, ReplayFactory* timeshift,
                                   SessionSet* sessions)
    : link_(std::move(link)),
      live_(std::move(channel)),
      config_(config),
      stats_(stats),
      ticket_(std::move(ticket)),
      replay_(std::move(replay)),
      timeshift_factory_(replay_ ? nullptr : timeshift),
      sessions_(sessions),
      queue_(config.max_queue_bytes) {
  ++stats_.clients;
  ++stats_.connections_total;
}

WebSocketSession::~WebSocketSession() {
  if (sessions_) sessions_->remove(in_set_);
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
  if (replay_) {
    replay_->close();
    replay_.reset();
  }
}

void WebSocketSession::drop_connection() {
  end_session();
  if (dead_) return;
  dead_ = true;
  if (timer_) timer_->cancel();
  link_.close();
}

void WebSocketSession::shutdown() {
  net::post(link_.get_executor(), [self = shared_from_this()] {
    self->close_with(CloseCode::GoingAway, "server shutting down");
  });
}

void WebSocketSession::close(std::uint16_t code, const std::string& reason) {
  net::post(link_.get_executor(), [self = shared_from_this(), code, reason] { self->close_with(code, reason); });
}

void WebSocketSession::run(std::string handshake_response, std::string_view early) {
  if (sessions_) sessions_->add(in_set_);
  if (link_.is_tls()) tls_in_ = std::make_unique<char[]>(kTlsReadBuffer);
  open_ = true;
  // The 101 response goes first; then, on this thread and before any later
  // deliver() (posted to the same thread), the join and its catch-up:
  // nothing is missed or doubled.
  queue_.push(Message::session_bytes(std::move(handshake_response)));
  switch_to(live_);
  // The 101 goes out now even when the channel has nothing to send yet (a
  // game a NATS edge is still waiting for): the catch-up did not flush.
  if (!writing_ && !flush_pending_) schedule_flush();
  if (!early.empty() && !consume(early)) return;
  start_read();
}

// ---- reading ---------------------------------------------------------------

void WebSocketSession::start_read() {
  if (dead_) return;
  if (link_.is_tls()) {
    link_.async_read_some(net::buffer(tls_in_.get(), kTlsReadBuffer),
                          [self = shared_from_this()](error_code ec, std::size_t n) { self->on_tls_read(ec, n); });
  } else {
    link_.async_wait_readable([self = shared_from_this()](error_code ec) { self->on_readable(ec); });
  }
}

void WebSocketSession::on_readable(error_code ec) {
  if (dead_) return;
  if (ec) return drop_connection();
  thread_local char chunk[kReadChunk];
  // A few chunks at most, then back to the loop: one busy client cannot
  // hold the thread (the next wait completes at once if more is there).
  for (int round = 0; round < 4; ++round) {
    const std::size_t n = link_.read_now(net::buffer(chunk), ec);
    if (ec == net::error::would_block || ec == net::error::try_again) break;
    if (ec) return drop_connection();  // end of stream (the peer left) or an error
    if (!consume({chunk, n})) return;
    if (n < kReadChunk) break;
  }
  if (inbound_) inbound_->shrink();
  start_read();
}

void WebSocketSession::on_tls_read(error_code ec, std::size_t bytes) {
  if (dead_) return;
  if (ec) return drop_connection();
  if (!consume({tls_in_.get(), bytes})) return;
  if (inbound_) inbound_->shrink();
  start_read();
}

bool WebSocketSession::consume(std::string_view bytes) {
  if (!inbound_) inbound_ = std::make_unique<WsInbound>(config_.max_inbound_message);
  inbound_->feed(bytes);
  WsInbound::Event ev;
  while (!dead_ && inbound_->next(ev)) {
    switch (ev.kind) {
      case WsInbound::Kind::Error:
        // A protocol violation or a message over --max-message-bytes.
        ++stats_.inbound_rejected;
        close_with(ev.code, ev.data);
        return !dead_;
      case WsInbound::Kind::Close:
        peer_closed_ = true;
        if (close_sent_) {
          drop_connection();  // the closing handshake is complete
          return false;
        }
        // The client said goodbye first: answer with its code, then close.
        close_with(ev.code == 1005 ? static_cast<std::uint16_t>(CloseCode::Normal) : ev.code, {});
        return !dead_;
      case WsInbound::Kind::Pong:
        break;
      case WsInbound::Kind::Ping:
        // One pong answers every ping not yet answered (RFC 6455 5.5.3), so
        // a ping flood costs one queued frame, never a growing queue.
        if (!closing_ && !pong_queued_) {
          pong_queued_ = true;
          queue_.push(Message::session_frame(0xA, ev.data));
          if (!writing_) write_next();
        }
        break;
      case WsInbound::Kind::Text:
      case WsInbound::Kind::Binary: {
        const auto now = std::chrono::steady_clock::now();
        if (now - window_start_ > std::chrono::seconds(1)) {
          window_start_ = now;
          window_messages_ = 0;
        }
        if (++window_messages_ > kMaxInboundPerSecond) {
          ++stats_.inbound_rejected;
          close_with(CloseCode::Policy, "too many messages");
          return !dead_;
        }
        if (ev.kind == WsInbound::Kind::Text && open_) on_text(ev.data);
        break;
      }
    }
  }
  return !dead_;
}

void WebSocketSession::on_text(std::string_view text) {
  const bool replaying = replay_ && !shifted_;
  if (!replaying && !timeshift_factory_) return;  // live spectators are otherwise read-only
  const auto m = read_spectator_message(text);  // spectator_message.hpp (fuzzed)
  if (!m) return;
  // A recording's replay gets every message of its spectator.
  if (replaying || (m->type == "replay" && shifted_)) return replay_->on_message(*m);
  if (m->type != "timeshift" || m->action.empty()) return;
  on_timeshift(m->action, m->time ? &*m->time : nullptr);
}

void WebSocketSession::on_timeshift(std::string_view action, const double* time) {
  if (action == "seek" && time) {
    if (!shifted_) {
      std::string error;
      auto replay = timeshift_factory_->open_timeshift(live_->name(), link_.get_executor(), error);
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
    replay_->on_message(SpectatorMessage{"replay", "seek", *time, std::nullopt});
  } else if (action == "live" && shifted_) {
    replay_->close();
    replay_.reset();
    shifted_ = false;
    switch_to(live_, Message::control(R"({"type":"timeshift","mode":"live"})"));
  }
}

// ---- writing ---------------------------------------------------------------

void WebSocketSession::switch_to(std::shared_ptr<Channel> channel, std::optional<Message> announce) {
  if (current_ && tap_) current_->leave(tap_.get());
  // A session on its io_context's thread (the relay's io_context per
  // thread) is served by its channel's per-thread task; otherwise by posts
  // (Channel::join decides).
  tap_ = std::make_shared<Tap>(weak_from_this(), ++epoch_, &link_.get_executor().context());
  current_ = std::move(channel);
  // The old source's backlog is of no use now; the handshake response and
  // pongs (session messages) still go out.
  std::vector<Message> queued;
  queue_.take_all(queued);
  for (auto& m : queued)
    if (m.kind == Message::Kind::Session) queue_.push(std::move(m));
  if (announce) enqueue(std::move(*announce));
  for (auto& m : current_->join(tap_)) enqueue(std::move(m));
  account_queue();
}

void WebSocketSession::deliver(std::uint64_t tap_epoch, const Message& m) {
  net::post(link_.get_executor(), [self = shared_from_this(), tap_epoch, m] {
    if (tap_epoch == self->epoch_) self->enqueue(m);
  });
}

void WebSocketSession::enqueue(Message m) {
  if (!open_ || closing_) return;
  queue_.push(std::move(m));
  account_queue();
  if (!writing_ && !flush_pending_) schedule_flush();
}

void WebSocketSession::fill(WriteBatch& batch) {
  // Everything that queued during the last write goes out as one batch.
  batch.clear();
  queue_.take_all(batch.messages);
  account_queue();
  pong_queued_ = false;  // a pong queued so far is in this batch
  for (const auto& m : batch.messages) {
    batch.buffers.push_back(net::buffer(*m.wire));
    batch.bytes += m.wire->size();
  }
}

void WebSocketSession::write_next() {
  // A loop, not recursion: each batch the kernel takes at once is followed
  // by whatever queued meanwhile.
  for (;;) {
    writing_ = false;
    if (dead_ || queue_.empty()) break;
    writing_ = true;
    ++stats_.writes;
    if (link_.is_tls()) {
      pending_ = std::make_unique<WriteBatch>();
      fill(*pending_);
      write_started_ = std::chrono::steady_clock::now();
      arm_timer(config_.stall_timeout);
      link_.async_write_all(pending_->buffers, [self = shared_from_this()](error_code ec, std::size_t n) {
        self->on_tls_write(ec, n);
      });
      return;
    }
    WriteBatch& batch = scratch_;
    fill(batch);
    error_code ec;
    const std::size_t sent = link_.write_now(batch.buffers, ec);
    if (ec && ec != net::error::would_block && ec != net::error::try_again) {
      writing_ = false;
      batch.clear();
      return drop_connection();
    }
    if (sent == batch.bytes) {
      batch_sent(batch);
      continue;
    }
    // The kernel took part: the rest waits for room, in a batch of the
    // session's own (the scratch serves the next session). Only now is the
    // stall clock started; a spectator that keeps up never arms it.
    ++stats_.partial_writes;
    pending_ = std::make_unique<WriteBatch>();
    pending_->messages.assign(std::make_move_iterator(batch.messages.begin()),
                              std::make_move_iterator(batch.messages.end()));
    pending_->buffers = batch.buffers;  // views of the moved strings: the strings stay where they were
    pending_->bytes = batch.bytes;
    batch.clear();
    skip_sent(*pending_, sent);
    write_started_ = std::chrono::steady_clock::now();
    arm_timer(config_.stall_timeout);
    link_.async_wait_writable([self = shared_from_this()](error_code e) { self->on_writable(e); });
    return;
  }
  // Everything is out. After our close frame: no more bytes from us; the
  // client has a moment to answer before the socket closes.
  if (closing_ && !close_sent_ && !dead_ && queue_.empty()) {
    close_sent_ = true;
    if (peer_closed_) return drop_connection();
    link_.shutdown_send();
    arm_timer(kCloseLinger);
  }
}

void WebSocketSession::skip_sent(WriteBatch& batch, std::size_t bytes) {
  auto& buffers = batch.buffers;
  auto first = buffers.begin();
  while (first != buffers.end() && bytes >= first->size()) bytes -= (first++)->size();
  if (first != buffers.end()) *first += bytes;
  buffers.erase(buffers.begin(), first);
}

void WebSocketSession::on_writable(error_code ec) {
  if (dead_) return;
  if (ec) return drop_connection();
  const std::size_t left = net::buffer_size(pending_->buffers);
  const std::size_t sent = link_.write_now(pending_->buffers, ec);
  if (ec && ec != net::error::would_block && ec != net::error::try_again) return drop_connection();
  if (sent < left) {
    skip_sent(*pending_, sent);
    link_.async_wait_writable([self = shared_from_this()](error_code e) { self->on_writable(e); });
    return;
  }
  if (timer_) timer_->cancel();
  batch_sent(*pending_);
  pending_.reset();
  write_next();
}

void WebSocketSession::on_tls_write(error_code ec, std::size_t) {
  if (dead_) return;
  if (ec) return drop_connection();
  if (timer_) timer_->cancel();
  batch_sent(*pending_);
  pending_.reset();
  write_next();
}

void WebSocketSession::batch_sent(WriteBatch& batch) {
  writing_ = false;
  stats_.bytes_sent += batch.bytes;
  std::size_t messages = 0;
  std::chrono::steady_clock::time_point now{};
  for (const auto& sent : batch.messages) {
    if (sent.kind == Message::Kind::Session) continue;  // a pong or a close: not the broadcast
    ++messages;
    if (!sent.binary()) continue;
    if (now == std::chrono::steady_clock::time_point{}) now = std::chrono::steady_clock::now();
    stats_.record_delay(std::chrono::duration<double, std::milli>(now - sent.published).count());
  }
  stats_.messages_sent += messages;
  batch.clear();
}

// ---- the one timer: a write stuck for the stall timeout, or a close lingering

void WebSocketSession::arm_timer(std::chrono::steady_clock::duration after) {
  if (!timer_) timer_ = std::make_unique<net::steady_timer>(link_.get_executor());
  timer_->expires_after(after);
  timer_->async_wait([self = shared_from_this()](error_code ec) { self->on_timer(ec); });
}

void WebSocketSession::on_timer(error_code ec) {
  if (ec == net::error::operation_aborted || dead_) return;
  if (close_sent_) return drop_connection();  // the client never answered our close
  if (!writing_) return;
  if (std::chrono::steady_clock::now() - write_started_ < config_.stall_timeout) return arm_timer(config_.stall_timeout / 4);
  // One write has not completed for stall_timeout: the client stopped
  // reading. Its kernel buffer is full, so a close frame cannot reach it
  // either; drop the connection and free its queue.
  ++stats_.closed_slow;
  // How long its write was stuck: the stall timeout plus up to a quarter of
  // it (the check's period); scripts/soak.sh checks it stays within 10 s.
  log_event("ws_closed_stalled",
            live_->name() + ": write stuck " +
                std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(
                                   std::chrono::steady_clock::now() - write_started_)
                                   .count()) +
                " ms");
  drop_connection();
}

void WebSocketSession::close_with(CloseCode code, std::string_view reason) {
  close_with(static_cast<std::uint16_t>(code), reason);
}

void WebSocketSession::close_with(std::uint16_t code, std::string_view reason) {
  if (closing_ || dead_) return;
  closing_ = true;
  end_session();
  // What was queued for the broadcast is of no use now; the close frame
  // follows any write in flight.
  std::vector<Message> dropped;
  queue_.take_all(dropped);
  account_queue();
  constexpr std::size_t kMaxReason = 123;  // RFC 6455: 125-byte payload, 2 of them the code
  reason = reason.substr(0, kMaxReason);
  std::string payload;
  payload.push_back(static_cast<char>(code >> 8));
  payload.push_back(static_cast<char>(code & 0xFF));
  payload.append(reason);
  queue_.push(Message::session_frame(0x8, payload));
  if (!writing_) write_next();
}

}  // namespace mc::relay
