#include "server/relay/http_session.hpp"

#include <boost/asio/dispatch.hpp>
#include <boost/beast/websocket.hpp>
#include <algorithm>
#include <chrono>

#include "server/relay/channel.hpp"
#include "server/relay/log.hpp"
#include "server/relay/metrics.hpp"
#include "server/relay/websocket_session.hpp"
#include "server/relay/ws_handshake.hpp"

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;

namespace mc::relay {
namespace {

// Boost 1.74's Beast speaks boost::string_view; the rest of us std's.
std::string_view sv(beast::string_view s) { return {s.data(), s.size()}; }
beast::string_view bsv(std::string_view s) { return {s.data(), s.size()}; }

// A response must be written within this time (a request must arrive
// within config.header_timeout).
constexpr auto kRequestTimeout = std::chrono::seconds(30);

http::response<http::string_body> text_response(const http::request<http::string_body>& req,
                                                http::status status, std::string body,
                                                std::string_view type = "text/plain; charset=utf-8") {
  http::response<http::string_body> res{status, req.version()};
  res.set(http::field::server, "matchcast");
  res.set(http::field::content_type, bsv(type));
  res.set(http::field::cache_control, "no-store");
  res.keep_alive(req.keep_alive());
  res.body() = std::move(body);
  res.prepare_payload();
  return res;
}

std::string_view path_of(std::string_view target) {
  return target.substr(0, target.find('?'));
}

}  // namespace

std::string query_param(std::string_view target, std::string_view key) {
  const auto q = target.find('?');
  if (q == std::string_view::npos) return {};
  std::string_view rest = target.substr(q + 1);
  while (!rest.empty()) {
    const auto amp = rest.find('&');
    const std::string_view pair = rest.substr(0, amp);
    const auto eq = pair.find('=');
    if (pair.substr(0, eq) == key) {
      if (eq == std::string_view::npos) return {};
      auto decoded = url_decode(pair.substr(eq + 1));
      return decoded ? *decoded : std::string{};
    }
    if (amp == std::string_view::npos) break;
    rest = rest.substr(amp + 1);
  }
  return {};
}

namespace {
Transport make_transport(net::ip::tcp::socket&& socket, const HttpContext& context) {
  if (context.tls) return Transport(beast::tcp_stream(std::move(socket)), *context.tls);
  return Transport(beast::tcp_stream(std::move(socket)));
}
}  // namespace

HttpSession::HttpSession(net::ip::tcp::socket&& socket, const HttpContext& context,
                         std::unique_ptr<ConnectionLimiter::Ticket> ticket)
    : stream_(make_transport(std::move(socket), context)), context_(context), ticket_(std::move(ticket)) {}

void HttpSession::run() {
  if (!stream_.is_tls())
    return net::dispatch(stream_.get_executor(),
                         beast::bind_front_handler(&HttpSession::do_read, shared_from_this()));
  stream_.tcp().expires_after(context_.config.header_timeout);
  stream_.tls().async_handshake(net::ssl::stream_base::server,
                                beast::bind_front_handler(&HttpSession::on_handshake, shared_from_this()));
}

void HttpSession::on_handshake(beast::error_code ec) {
  if (ec) return;  // not TLS, a bad client, or a timeout: nothing to answer
  do_read();
}

void HttpSession::shutdown_send() {
  beast::error_code ignored;
  stream_.tcp().socket().shutdown(net::ip::tcp::socket::shutdown_send, ignored);
}

void HttpSession::do_read() {
  parser_.emplace();
  parser_->body_limit(context_.config.max_http_body);
  parser_->header_limit(8 * 1024);
  // Slow headers and half-open connections: the whole request in time, or
  // the connection closes (an idle keep-alive connection too).
  stream_.tcp().expires_after(context_.config.header_timeout);
  http::async_read(stream_, buffer_, *parser_,
                   beast::bind_front_handler(&HttpSession::on_read, shared_from_this()));
}

void HttpSession::on_read(beast::error_code ec, std::size_t) {
  if (ec == http::error::end_of_stream) return shutdown_send();
  if (ec) {
    // A malformed or oversized request: answer 400 when the connection can
    // still carry it, then close.
    if (ec != net::error::operation_aborted && ec != beast::error::timeout) {
      http::request<http::string_body> dummy{http::verb::get, "/", 11};
      dummy.keep_alive(false);
      send(text_response(dummy, http::status::bad_request, "bad request\n"));
    }
    return;
  }
  ++context_.stats.http_requests;
  http::request<http::string_body> req = parser_->release();
  const std::string_view path = path_of(sv(req.target()));

  if (beast::websocket::is_upgrade(req)) return upgrade(std::move(req));
  if (path.rfind("/control/", 0) == 0) return handle_control(req);

  if (req.method() != http::verb::get && req.method() != http::verb::head)
    return send(text_response(req, http::status::method_not_allowed, "GET or HEAD only\n"));

  if (path == "/healthz") return send(text_response(req, http::status::ok, "ok\n"));
  if (path == "/metrics")
    return send(text_response(req, http::status::ok, render_metrics(context_.stats, context_.channels),
                              "text/plain; version=0.0.4"));
  if (path == "/recordings")
    return send(text_response(req, http::status::ok,
                              context_.replays ? context_.replays->list_json() : "{\"recordings\":[]}",
                              "application/json"));
  if (path == "/channels")
    return send(text_response(req, http::status::ok, render_channels(context_.channels),
                              "application/json"));

  auto file = context_.files.resolve(sv(req.target()));
  if (!file) {
    ++context_.stats.http_not_found;
    return send(text_response(req, http::status::not_found, "not found\n"));
  }
  http::file_body::value_type body;
  body.open(file->c_str(), beast::file_mode::scan, ec);
  if (ec) {
    ++context_.stats.http_not_found;
    return send(text_response(req, http::status::not_found, "not found\n"));
  }
  const auto size = body.size();
  if (req.method() == http::verb::head) {
    http::response<http::empty_body> res{http::status::ok, req.version()};
    res.set(http::field::content_type, bsv(mime_type(*file)));
    res.content_length(size);
    res.keep_alive(req.keep_alive());
    return send(std::move(res));
  }
  http::response<http::file_body> res{std::piecewise_construct, std::make_tuple(std::move(body)),
                                      std::make_tuple(http::status::ok, req.version())};
  res.set(http::field::server, "matchcast");
  res.set(http::field::content_type, bsv(mime_type(*file)));
  res.content_length(size);
  res.keep_alive(req.keep_alive());
  send(std::move(res));
}

void HttpSession::upgrade(http::request<http::string_body>&& req) {
  const std::string_view path = path_of(sv(req.target()));
  if (path != "/ws") return send(text_response(req, http::status::not_found, "no such stream\n"));
  auto handshake = accept_upgrade(req);
  if (!handshake.ok) {
    auto res = text_response(req, handshake.status, handshake.error + "\n");
    if (handshake.status == http::status::upgrade_required) res.set(http::field::sec_websocket_version, "13");
    return send(std::move(res));
  }
  const auto& origins = context_.config.allowed_origins;
  if (!origins.empty()) {
    const std::string origin(sv(req[http::field::origin]));
    if (std::find(origins.begin(), origins.end(), origin) == origins.end()) {
      ++context_.stats.refused_origin;
      return send(text_response(req, http::status::forbidden, "origin not allowed\n"));
    }
  }
  if (static_cast<std::size_t>(context_.stats.clients.load()) >= context_.config.max_clients) {
    ++context_.stats.refused_full;
    return send(text_response(req, http::status::service_unavailable, "server full\n"));
  }
  std::shared_ptr<ReplaySource> replay;
  std::shared_ptr<Channel> channel;
  const std::string recording = query_param(sv(req.target()), "recording");
  if (!recording.empty()) {
    // A private replay: the spectator steers its own copy of the recording.
    std::string error;
    if (context_.replays) replay = context_.replays->open(recording, stream_.get_executor(), error);
    if (!replay) return send(text_response(req, http::status::not_found, "no such recording\n"));
    channel = replay->channel();
  } else {
    const std::string name = query_param(sv(req.target()), "channel");
    // A NATS edge may subscribe to a game it does not carry yet.
    channel = name.empty() ? context_.channels.default_channel() : context_.channels.find_or_request(name);
    if (!channel) return send(text_response(req, http::status::not_found, "no such channel\n"));
  }
  // The connection's per-address slot, taken when it was accepted, goes
  // with it to the WebSocket session.
  auto ticket = std::move(ticket_);
  // Beast has parsed the request; from here the session runs the
  // connection itself on the bare socket (or the TLS stream).
  stream_.tcp().expires_never();
  const auto early = beast::buffers_to_string(buffer_.data());
  // Every connection runs on one of the relay's io_contexts (the listener
  // hands each to one).
  const auto executor = stream_.get_executor();
  const auto* home = executor.target<net::io_context::executor_type>();
  if (!home) return send(text_response(req, http::status::internal_server_error, "not on an I/O thread\n"));
  SpectatorLink link = stream_.is_tls() ? SpectatorLink(stream_.release_tls(), *home)
                                        : SpectatorLink(stream_.release_socket(), *home);
  std::make_shared<WebSocketSession>(std::move(link), std::move(channel), context_.config, context_.stats,
                                     std::move(ticket), std::move(replay), context_.replays, context_.sessions)
      ->run(std::move(handshake.response), early);
}

void HttpSession::handle_control(const http::request<http::string_body>& req) {
  // Spectators are read-only: every control action needs the operator's token.
  const std::string& token = context_.config.control_token;
  if (token.empty() || !context_.control)
    return send(text_response(req, http::status::forbidden, "control is disabled\n"));
  if (req.method() != http::verb::post)
    return send(text_response(req, http::status::method_not_allowed, "POST only\n"));
  const std::string_view auth = sv(req[http::field::authorization]);
  const std::string expected = "Bearer " + token;
  // Compare in constant time: the token is a secret.
  bool match = auth.size() == expected.size();
  unsigned char diff = 0;
  for (std::size_t i = 0; match && i < auth.size(); ++i)
    diff |= static_cast<unsigned char>(auth[i] ^ expected[i]);
  if (!match || diff != 0) {
    log_event("control_refused", std::string(path_of(sv(req.target()))));
    return send(text_response(req, http::status::unauthorized, "bad or missing token\n"));
  }
  const std::string action(path_of(sv(req.target())).substr(std::string_view("/control/").size()));
  const std::string channel = query_param(sv(req.target()), "channel");
  std::string message;
  const bool ok = context_.control->control(action, channel, message);
  log_event(ok ? "control" : "control_failed", action + " " + channel + ": " + message);
  send(text_response(req, ok ? http::status::ok : http::status::bad_request, message + "\n"));
}

template <class Response>
void HttpSession::send(Response&& res) {
  using R = std::decay_t<Response>;
  auto sp = std::make_shared<R>(std::forward<Response>(res));
  response_ = sp;
  const bool keep_alive = sp->keep_alive();
  stream_.tcp().expires_after(kRequestTimeout);
  http::async_write(stream_, *sp,
                    beast::bind_front_handler(&HttpSession::on_write, shared_from_this(), keep_alive));
}

void HttpSession::on_write(bool keep_alive, beast::error_code ec, std::size_t) {
  response_.reset();
  if (ec) return;
  if (!keep_alive) return shutdown_send();
  do_read();
}

}  // namespace mc::relay
