// The byte stream of one client connection: plain TCP or TLS (chosen at run
// time, so that sessions are not templates), and the write gate that lets a
// spectator's session write pre-framed WebSocket messages itself while
// Beast's websocket stream, layered on top, still does the handshake, the
// reads, the pong and close replies.
//
// Why a gate: Beast can only write one message per async_write, and a batch
// of N queued frames would cost N writes. The session writes a batch with
// one gathered write instead (write_raw). Bytes from two writers must never
// interleave on the socket, so every write goes through here:
//   - a Beast write that arrives while a raw write is in flight is parked
//     and started when the raw write ends;
//   - a raw write starts only when no Beast write is in flight (can_write_raw);
//     when Beast's last write ends, the idle hook tells the session to go on.
// Beast writes a frame with one composed async_write whose continuations
// run inline on the session's strand, so "no write_some in flight" means no
// Beast frame is half written. Everything here runs on that strand.
//
// TLS: beast::ssl_stream coalesces a buffer sequence into one TLS record
// per write_some (flat_stream), so a raw batch is also one SSL_write there.
#pragma once

#include <boost/asio/ssl/context.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/ssl/ssl_stream.hpp>
#include <boost/beast/websocket/teardown.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

namespace mc::relay {

class Transport {
 public:
  using executor_type = boost::beast::tcp_stream::executor_type;
  using tls_stream = boost::beast::ssl_stream<boost::beast::tcp_stream>;

  explicit Transport(boost::beast::tcp_stream&& plain) : plain_(std::move(plain)) {}
  Transport(boost::beast::tcp_stream&& plain, boost::asio::ssl::context& tls)
      : tls_(std::in_place, std::move(plain), tls) {}
  Transport(Transport&&) = default;

  executor_type get_executor() { return tcp().get_executor(); }
  bool is_tls() const { return tls_.has_value(); }
  // The TCP stream under everything: timeouts, the peer's address, close.
  boost::beast::tcp_stream& tcp() { return tls_ ? tls_->next_layer() : *plain_; }
  tls_stream& tls() { return *tls_; }

  // Whoever owns this transport: kept alive by every pending completion.
  void set_owner(std::weak_ptr<void> owner) { owner_ = std::move(owner); }
  // Called on the strand when the last Beast write ends (the session may
  // then write again).
  void on_idle(std::function<void()> hook) { idle_hook_ = std::move(hook); }

  // AsyncReadStream.
  template <class MutableBuffers, class Handler>
  void async_read_some(const MutableBuffers& buffers, Handler&& handler) {
    if (tls_) tls_->async_read_some(buffers, std::forward<Handler>(handler));
    else plain_->async_read_some(buffers, std::forward<Handler>(handler));
  }

  // AsyncWriteStream, for Beast (and HTTP): parked while a raw write runs.
  template <class ConstBuffers, class Handler>
  void async_write_some(const ConstBuffers& buffers, Handler&& handler) {
    if (raw_writing_) {
      auto h = std::make_shared<std::decay_t<Handler>>(std::forward<Handler>(handler));
      parked_.push_back([this, buffers, h] { start_beast_write(buffers, std::move(*h)); });
      return;
    }
    start_beast_write(buffers, std::forward<Handler>(handler));
  }

  // True when the session may start a raw write now.
  bool can_write_raw() const { return !raw_writing_ && beast_writes_ == 0 && parked_.empty(); }

  // Writes every byte of `buffers` (one gathered write; more syscalls only
  // if the kernel takes part of it). The buffers must stay alive until
  // `handler(ec, bytes)` runs. Requires can_write_raw().
  template <class ConstBuffers, class Handler>
  void async_write_raw(const ConstBuffers& buffers, Handler&& handler) {
    raw_writing_ = true;
    auto done = [this, keep = owner_.lock(), h = std::forward<Handler>(handler)](
                    boost::beast::error_code ec, std::size_t n) mutable {
      raw_writing_ = false;
      // Beast's parked writes (a pong, a close frame) go first.
      auto parked = std::move(parked_);
      parked_.clear();
      for (auto& p : parked) p();
      h(ec, n);
    };
    // Plain TCP: straight on the socket. tcp_stream's timeout machinery
    // (unused: sessions run with expires_never) cost a tenth of the relay's
    // CPU per frame in a profile.
    if (tls_) boost::asio::async_write(*tls_, buffers, std::move(done));
    else boost::asio::async_write(plain_->socket(), buffers, std::move(done));
  }

  // Plain TCP only: one non-blocking gathered send of what the kernel takes
  // now. Returns the bytes written (0 with net::error::would_block when the
  // socket buffer is full). A batch the kernel takes whole (nearly always,
  // for a reader keeping up) then costs one syscall and no asynchronous
  // operation: the Asio op, its completion and handler dispatch were a
  // fifth of the relay's CPU per frame at 5,000 spectators. Requires
  // can_write_raw() and !is_tls().
  template <class ConstBuffers>
  std::size_t try_write_raw(const ConstBuffers& buffers, boost::beast::error_code& ec) {
    auto& socket = plain_->socket();
    if (!socket.non_blocking()) socket.non_blocking(true, ec);
    if (ec) return 0;
    return socket.write_some(buffers, ec);
  }

  // Ends the connection at once (a stalled client: no goodbye can reach it).
  void close() {
    boost::beast::error_code ignored;
    tcp().socket().close(ignored);
  }

  // Beast's timeouts close the socket through this (found by argument-dependent lookup).
  friend void beast_close_socket(Transport& t) { t.close(); }

  // websocket::stream's close calls these (found by argument-dependent lookup).
  template <class Handler>
  friend void async_teardown(boost::beast::role_type role, Transport& t, Handler&& handler) {
    using boost::beast::websocket::async_teardown;
    if (t.tls_) async_teardown(role, *t.tls_, std::forward<Handler>(handler));
    else async_teardown(role, *t.plain_, std::forward<Handler>(handler));
  }
  friend void teardown(boost::beast::role_type role, Transport& t, boost::beast::error_code& ec) {
    using boost::beast::websocket::teardown;
    if (t.tls_) teardown(role, *t.tls_, ec);
    else teardown(role, *t.plain_, ec);
  }

 private:
  template <class ConstBuffers, class Handler>
  void start_beast_write(const ConstBuffers& buffers, Handler&& handler) {
    ++beast_writes_;
    auto done = [this, keep = owner_.lock(), h = std::forward<Handler>(handler)](
                    boost::beast::error_code ec, std::size_t n) mutable {
      --beast_writes_;
      // Beast's continuation runs first: if its frame is not finished it
      // starts the next write_some right here, and the count is up again.
      h(ec, n);
      if (beast_writes_ == 0 && !raw_writing_ && idle_hook_) idle_hook_();
    };
    if (tls_) tls_->async_write_some(buffers, std::move(done));
    else plain_->async_write_some(buffers, std::move(done));
  }

  std::optional<boost::beast::tcp_stream> plain_;
  std::optional<tls_stream> tls_;
  std::weak_ptr<void> owner_;
  std::function<void()> idle_hook_;
  std::vector<std::function<void()>> parked_;
  int beast_writes_ = 0;
  bool raw_writing_ = false;
};

}  // namespace mc::relay
