// One HTTP connection: serves static files from the web root, /healthz, and
// hands WebSocket upgrades on /ws to a WebSocketSession.
#pragma once

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <memory>
#include <optional>

#include "server/relay/relay_config.hpp"
#include "server/relay/relay_stats.hpp"
#include "server/relay/static_files.hpp"

namespace mc::relay {

class Channel;

// What an HTTP session needs from the server it belongs to.
struct HttpContext {
  const RelayConfig& config;
  RelayStats& stats;
  const StaticFiles& files;
  std::shared_ptr<Channel> channel;  // the one game on /ws
};

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket&& socket, const HttpContext& context);
  void run();

 private:
  void do_read();
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  void on_write(bool keep_alive, boost::beast::error_code ec, std::size_t bytes);
  template <class Response>
  void send(Response&& res);

  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  const HttpContext& context_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  std::shared_ptr<void> response_;  // keeps the response alive during the write
};

}  // namespace mc::relay
