#include "server/relay/listener.hpp"

#include <boost/asio/strand.hpp>
#include <boost/beast/core/bind_handler.hpp>

#include "server/relay/log.hpp"

namespace net = boost::asio;
namespace beast = boost::beast;

namespace mc::relay {

Listener::Listener(std::vector<net::io_context*> threads, const HttpContext& context)
    : threads_(std::move(threads)), acceptor_(*threads_.front()), retry_(*threads_.front()), context_(context) {}

bool Listener::open(const net::ip::tcp::endpoint& endpoint, std::string& error) {
  beast::error_code ec;
  acceptor_.open(endpoint.protocol(), ec);
  if (!ec) acceptor_.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) acceptor_.bind(endpoint, ec);
  if (!ec) acceptor_.listen(net::socket_base::max_listen_connections, ec);
  // on_accept() takes what else is waiting with non-blocking accepts.
  if (!ec) acceptor_.non_blocking(true, ec);
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
    self->retry_.cancel();
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
  if (ec == net::error::operation_aborted || !acceptor_.is_open()) return;  // closed
  if (ec) {
    // Out of file descriptors and similar: log (once a second at most, with
    // the failures since), and try again a little later: at once would spin
    // on the same error for as long as the queue stays full.
    ++accept_failures_;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_failure_log_ >= std::chrono::seconds(1)) {
      log_event("accept_failed", ec.message() + " (" + std::to_string(accept_failures_) +
                                     " failed accepts since the last such line; retrying every 50 ms)");
      accept_failures_ = 0;
      last_failure_log_ = now;
    }
    retry_.expires_after(std::chrono::milliseconds(50));
    retry_.async_wait([self = shared_from_this()](beast::error_code e) {
      if (!e && self->acceptor_.is_open()) self->do_accept();  // not after close()
    });
    return;
  }
  admit(std::move(socket));
  // Everything else already waiting in the listen queue, now. Each
  // async_accept completes only after the handlers queued before it, and
  // while thousands of spectators are being sent a frame that queue is one
  // whole fan-out long (tens of ms): one connection per pass let a connect
  // storm time out in the kernel's backlog. The batch is bounded so that
  // a storm cannot hold up the frames either.
  constexpr int kBatch = 128;
  for (int i = 0; i < kBatch; ++i) {
    net::ip::tcp::socket next(*threads_[next_ % threads_.size()]);
    acceptor_.accept(next, ec);
    if (ec == net::error::would_block || ec == net::error::try_again) break;
    if (ec) break;  // the async_accept below meets it again and says so
    ++next_;
    admit(std::move(next));
  }
  do_accept();
}

void Listener::admit(net::ip::tcp::socket socket) {
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

}  // namespace mc::relay
