#include "server/relay/listener.hpp"

#include <boost/asio/strand.hpp>
#include <boost/beast/core/bind_handler.hpp>

#include "server/relay/log.hpp"

namespace net = boost::asio;
namespace beast = boost::beast;

namespace mc::relay {

Listener::Listener(std::vector<net::io_context*> threads, const HttpContext& context)
    : threads_(std::move(threads)), acceptor_(*threads_.front()), context_(context) {}

bool Listener::open(const net::ip::tcp::endpoint& endpoint, std::string& error) {
  beast::error_code ec;
  acceptor_.open(endpoint.protocol(), ec);
  if (!ec) acceptor_.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) acceptor_.bind(endpoint, ec);
  if (!ec) acceptor_.listen(net::socket_base::max_listen_connections, ec);
  if (ec) {
    error = "cannot listen on " + endpoint.address().to_string() + ":" +
            std::to_string(endpoint.port()) + ": " + ec.message();
    return false;
  }
  return true;
}

std::uint16_t Listener::port() const {
  beast::error_code ec;
  auto ep = acceptor_.local_endpoint(ec);
  return ec ? 0 : ep.port();
}

void Listener::run() { do_accept(); }

void Listener::close() {
  net::post(acceptor_.get_executor(), [self = shared_from_this()] {
    beast::error_code ec;
    self->acceptor_.close(ec);
  });
}

void Listener::do_accept() {
  net::io_context& home = *threads_[next_++ % threads_.size()];
  acceptor_.async_accept(home,
                         beast::bind_front_handler(&Listener::on_accept, shared_from_this()));
}

void Listener::refuse(net::ip::tcp::socket& socket) {
  // One non-blocking write into the fresh socket's empty buffer, then close:
  // a refusal costs no session, no timer and no wait.
  static constexpr std::string_view kTooMany =
      "HTTP/1.1 429 Too Many Requests\r\nServer: matchcast\r\nContent-Type: text/plain; charset=utf-8\r\n"
      "Content-Length: 39\r\nConnection: close\r\n\r\ntoo many connections from your address\n";
  beast::error_code ignored;
  socket.non_blocking(true, ignored);
  socket.write_some(net::buffer(kTooMany.data(), kTooMany.size()), ignored);
  socket.shutdown(net::ip::tcp::socket::shutdown_send, ignored);
  socket.close(ignored);
}

void Listener::on_accept(beast::error_code ec, net::ip::tcp::socket socket) {
  if (ec == net::error::operation_aborted) return;  // closed
  if (ec) {
    // Out of file descriptors and similar: log and keep accepting.
    log_event("accept_failed", ec.message());
  } else {
    // A live stream wants each frame on the wire now: without TCP_NODELAY,
    // Nagle holds a message that follows another (a stamina update right
    // after a frame) until the client's delayed ACK, up to 40 ms.
    beast::error_code ignored;
    socket.set_option(net::ip::tcp::no_delay(true), ignored);
    if (context_.config.socket_send_buffer > 0) {
      socket.set_option(net::socket_base::send_buffer_size(static_cast<int>(context_.config.socket_send_buffer)),
                        ignored);
    }
    // Every connection takes its address's slot at once, before it has
    // said anything: a host that opens many (slow headers, half-open
    // sockets, a flood of upgrades) is refused past the limit, and other
    // addresses are not affected.
    beast::error_code peer_ec;
    const auto peer = socket.remote_endpoint(peer_ec);
    auto ticket = peer_ec ? nullptr : context_.limiter->acquire(peer.address());
    if (!ticket) {
      if (!peer_ec) ++context_.stats.refused_per_ip;
      refuse(socket);
    } else {
      std::make_shared<HttpSession>(std::move(socket), context_, std::move(ticket))->run();
    }
  }
  do_accept();
}

}  // namespace mc::relay
