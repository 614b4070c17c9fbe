// One HTTP connection (plain, or TLS after its handshake): serves static
// files from the web root, /healthz, and hands WebSocket upgrades on /ws to
// a WebSocketSession.
#pragma once

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <memory>
#include <optional>

#include "server/relay/channel_registry.hpp"
#include "server/relay/connection_limiter.hpp"
#include "server/relay/control_handler.hpp"
#include "server/relay/relay_config.hpp"
#include "server/relay/replay_source.hpp"
#include "server/relay/relay_stats.hpp"
#include "server/relay/session_set.hpp"
#include "server/relay/static_files.hpp"
#include "server/relay/transport.hpp"

namespace mc::relay {

// What an HTTP session needs from the server it belongs to.
struct HttpContext {
  const RelayConfig& config;
  RelayStats& stats;
  const StaticFiles& files;
  ChannelRegistry& channels;             // /ws?channel=NAME
  std::shared_ptr<ConnectionLimiter> limiter;
  ControlHandler* control = nullptr;     // /control/...; nullptr = none
  ReplayFactory* replays = nullptr;      // /ws?recording=NAME, /recordings; nullptr = none
  SessionSet* sessions = nullptr;        // every WebSocket session, for a graceful stop
  boost::asio::ssl::context* tls = nullptr;  // set: HTTPS and WSS only
};

// The value of `key` in a target's query string ("/ws?channel=a&x=1"), or "".
std::string query_param(std::string_view target, std::string_view key);

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  // `ticket`: the connection's per-address slot (connection_limiter), held
  // until it ends, by this session or the WebSocket session it becomes.
  HttpSession(boost::asio::ip::tcp::socket&& socket, const HttpContext& context,
              std::unique_ptr<ConnectionLimiter::Ticket> ticket);
  void run();

 private:
  void on_handshake(boost::beast::error_code ec);
  void do_read();
  void shutdown_send();
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  void on_write(bool keep_alive, boost::beast::error_code ec, std::size_t bytes);
  void upgrade(boost::beast::http::request<boost::beast::http::string_body>&& req);
  void handle_control(const boost::beast::http::request<boost::beast::http::string_body>& req);
  template <class Response>
  void send(Response&& res);

  Transport stream_;
  boost::beast::flat_buffer buffer_;
  const HttpContext& context_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  std::shared_ptr<void> response_;  // keeps the response alive during the write
  std::unique_ptr<ConnectionLimiter::Ticket> ticket_;
};

}  // namespace mc::relay
