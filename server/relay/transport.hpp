// The byte stream of one client connection while it speaks HTTP: plain TCP or
// TLS (chosen at run time, so that sessions are not templates). Beast reads
// requests and writes responses on it, with tcp_stream's timeouts. After a
// WebSocket upgrade the session takes the socket (or the TLS stream) out of
// it and runs the connection itself (spectator_link.hpp).
#pragma once

#include <boost/asio/ssl/context.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/ssl/ssl_stream.hpp>
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

  // AsyncReadStream and AsyncWriteStream, for Beast's HTTP.
  template <class MutableBuffers, class Handler>
  void async_read_some(const MutableBuffers& buffers, Handler&& handler) {
    if (tls_) tls_->async_read_some(buffers, std::forward<Handler>(handler));
    else plain_->async_read_some(buffers, std::forward<Handler>(handler));
  }
  template <class ConstBuffers, class Handler>
  void async_write_some(const ConstBuffers& buffers, Handler&& handler) {
    if (tls_) tls_->async_write_some(buffers, std::forward<Handler>(handler));
    else plain_->async_write_some(buffers, std::forward<Handler>(handler));
  }

  // The connection, handed to a WebSocket session after the upgrade: the
  // bare socket (no timers, no rate policy), or the whole TLS stream.
  boost::asio::ip::tcp::socket release_socket() { return plain_->release_socket(); }
  std::unique_ptr<tls_stream> release_tls() { return std::make_unique<tls_stream>(std::move(*tls_)); }

  // Ends the connection at once.
  void close() {
    boost::beast::error_code ignored;
    tcp().socket().close(ignored);
  }

  // Beast's timeouts close the socket through this (found by argument-dependent lookup).
  friend void beast_close_socket(Transport& t) { t.close(); }

 private:
  std::optional<boost::beast::tcp_stream> plain_;
  std::optional<tls_stream> tls_;
};

}  // namespace mc::relay
