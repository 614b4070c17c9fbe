// Accepts TCP connections and gives each to an HttpSession on one of the
// relay's I/O threads (one io_context per thread, chosen in turn): a session
// then runs on a single thread and needs no strand.
#pragma once

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/error.hpp>
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include "server/relay/http_session.hpp"

namespace mc::relay {

class Listener : public std::enable_shared_from_this<Listener> {
 public:
  // `threads`: one io_context per I/O thread; the acceptor runs on the first.
  Listener(std::vector<boost::asio::io_context*> threads, const HttpContext& context);
  // Binds and listens; false with `error` when the endpoint is unusable.
  bool open(const boost::asio::ip::tcp::endpoint& endpoint, std::string& error);
  void run();
  void close();
  std::uint16_t port() const;

 private:
  void do_accept();
  // Admits this connection and any others already waiting (a bounded batch).
  void on_accept(boost::beast::error_code ec, boost::asio::ip::tcp::socket socket);
  // Sets the socket up and gives it an HttpSession, or refuses it (per-IP cap).
  void admit(boost::asio::ip::tcp::socket socket);
  // Answers 429 and closes: the address holds max_connections_per_ip.
  void refuse(boost::asio::ip::tcp::socket& socket);

  std::vector<boost::asio::io_context*> threads_;
  std::size_t next_ = 0;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer retry_;  // after an accept error (out of descriptors)
  std::uint64_t accept_failures_ = 0;  // since the last accept_failed line
  std::chrono::steady_clock::time_point last_failure_log_{};
  const HttpContext& context_;
};

}  // namespace mc::relay
