// The connection of one spectator after the WebSocket upgrade: the bare TCP
// socket, or the TLS stream. On plain TCP the session works on readiness,
// as uWebSockets does: it waits for the socket to be readable or writable
// and then reads or writes without blocking, so an idle spectator holds no
// read buffer and no pending read operation's buffer, and a batch the kernel
// takes whole costs one sendmsg and no asynchronous operation. TLS keeps
// asynchronous reads and writes (it needs its own buffers anyway).
#pragma once

#include <unistd.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <memory>
#include <utility>

#include "server/relay/transport.hpp"

namespace mc::relay {

class SpectatorLink {
 public:
  using tls_stream = Transport::tls_stream;
  // The socket is typed on its thread's io_context executor, not on
  // any_io_executor: that is ~40 bytes less in the socket and as many in
  // every pending wait (its handler keeps a copy of the executor), per
  // spectator. The relay runs every connection on an io_context.
  using executor_type = boost::asio::io_context::executor_type;
  using socket_type = boost::asio::basic_stream_socket<boost::asio::ip::tcp, executor_type>;

  // `home`: the io_context executor the connection runs on.
  SpectatorLink(boost::asio::ip::tcp::socket&& socket, executor_type home) : socket_(rebind(std::move(socket), home)) {}
  SpectatorLink(std::unique_ptr<tls_stream> tls, executor_type home) : socket_(home), tls_(std::move(tls)) {}

  executor_type get_executor() { return socket_.get_executor(); }
  bool is_tls() const { return tls_ != nullptr; }

  // Plain TCP: what the kernel takes or has now, without blocking (0 with
  // would_block when it has no room or no bytes).
  template <class ConstBuffers>
  std::size_t write_now(const ConstBuffers& buffers, boost::system::error_code& ec) {
    if (!socket_.non_blocking()) socket_.non_blocking(true, ec);
    if (ec) return 0;
    return socket_.write_some(buffers, ec);
  }
  std::size_t read_now(boost::asio::mutable_buffer buffer, boost::system::error_code& ec) {
    if (!socket_.non_blocking()) socket_.non_blocking(true, ec);
    if (ec) return 0;
    return socket_.read_some(buffer, ec);
  }
  template <class Handler>
  void async_wait_readable(Handler&& h) { socket_.async_wait(socket_type::wait_read, std::forward<Handler>(h)); }
  template <class Handler>
  void async_wait_writable(Handler&& h) { socket_.async_wait(socket_type::wait_write, std::forward<Handler>(h)); }

  // TLS: asynchronous reads and whole writes.
  template <class Handler>
  void async_read_some(boost::asio::mutable_buffer buffer, Handler&& h) {
    tls_->async_read_some(buffer, std::forward<Handler>(h));
  }
  template <class ConstBuffers, class Handler>
  void async_write_all(const ConstBuffers& buffers, Handler&& h) {
    boost::asio::async_write(*tls_, buffers, std::forward<Handler>(h));
  }

  // After our close frame: no more bytes from us (TLS: the frame is the goodbye).
  void shutdown_send() {
    boost::system::error_code ignored;
    if (tls_) tls_->next_layer().socket().shutdown(socket_type::shutdown_send, ignored);
    else socket_.shutdown(socket_type::shutdown_send, ignored);
  }
  // Ends the connection at once (a stalled client: no goodbye can reach it).
  void close() {
    boost::system::error_code ignored;
    if (tls_) tls_->next_layer().socket().close(ignored);
    else socket_.close(ignored);
  }

 private:
  // The same connection (the same descriptor, its options kept) on a socket
  // of executor_type. A socket that cannot move stays closed: the session
  // then ends on its first read or write.
  static socket_type rebind(boost::asio::ip::tcp::socket&& from, executor_type home) {
    socket_type to(home);
    boost::system::error_code ec;
    const auto protocol = from.local_endpoint(ec).protocol();
    if (ec) return to;
    const auto fd = from.release(ec);
    if (ec) return to;
    to.assign(protocol, fd, ec);
    if (ec) ::close(fd);
    return to;
  }

  socket_type socket_;  // plain TCP; for TLS an unused closed socket of the same executor
  std::unique_ptr<tls_stream> tls_;
};

}  // namespace mc::relay
