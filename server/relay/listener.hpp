// Accepts TCP connections and gives each to an HttpSession on its own strand.
#pragma once

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/error.hpp>
#include <memory>

#include "server/relay/http_session.hpp"

namespace mc::relay {

class Listener : public std::enable_shared_from_this<Listener> {
 public:
  Listener(boost::asio::io_context& ioc, const HttpContext& context);
  // Binds and listens; false with `error` when the endpoint is unusable.
  bool open(const boost::asio::ip::tcp::endpoint& endpoint, std::string& error);
  void run();
  void close();
  std::uint16_t port() const;

 private:
  void do_accept();
  void on_accept(boost::beast::error_code ec, boost::asio::ip::tcp::socket socket);

  boost::asio::io_context& ioc_;
  boost::asio::ip::tcp::acceptor acceptor_;
  const HttpContext& context_;
};

}  // namespace mc::relay
