#include "server/relay/ws_handshake.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>

// Beast's own SHA-1 and base64, the ones its websocket::stream handshake uses.
#include <boost/beast/core/detail/base64.hpp>
#include <boost/beast/core/detail/sha1.hpp>

namespace http = boost::beast::http;

namespace mc::relay {
namespace {

std::string_view sv(boost::beast::string_view s) { return {s.data(), s.size()}; }

// True when the comma-separated header value holds `token` (any case).
bool has_token(std::string_view value, std::string_view token) {
  while (!value.empty()) {
    const auto comma = value.find(',');
    std::string_view item = value.substr(0, comma);
    while (!item.empty() && (item.front() == ' ' || item.front() == '\t')) item.remove_prefix(1);
    while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) item.remove_suffix(1);
    if (item.size() == token.size() &&
        std::equal(item.begin(), item.end(), token.begin(), [](char a, char b) {
          return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
        }))
      return true;
    if (comma == std::string_view::npos) break;
    value.remove_prefix(comma + 1);
  }
  return false;
}

// A key is 16 random bytes in base64: 24 characters, the last two "==".
bool valid_key(std::string_view key) {
  if (key.size() != 24 || key[22] != '=' || key[23] != '=') return false;
  return std::all_of(key.begin(), key.end() - 2, [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/';
  });
}

HandshakeResult refuse(http::status status, std::string why) {
  HandshakeResult r;
  r.status = status;
  r.error = std::move(why);
  return r;
}

}  // namespace

std::array<unsigned char, 20> sha1(std::string_view data) {
  namespace bd = boost::beast::detail;
  bd::sha1_context ctx;
  bd::init(ctx);
  bd::update(ctx, data.data(), data.size());
  std::array<unsigned char, 20> out;
  static_assert(bd::sha1_context::digest_size == 20);
  bd::finish(ctx, out.data());
  return out;
}

std::string base64(const unsigned char* data, std::size_t n) {
  namespace b64 = boost::beast::detail::base64;
  std::string out(b64::encoded_size(n), '\0');
  out.resize(b64::encode(out.data(), data, n));
  return out;
}

std::string websocket_accept(std::string_view client_key) {
  static constexpr std::string_view kGuid = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";
  std::string input(client_key);
  input += kGuid;
  const auto digest = sha1(input);
  return base64(digest.data(), digest.size());
}

HandshakeResult accept_upgrade(const http::request<http::string_body>& req) {
  if (req.method() != http::verb::get) return refuse(http::status::bad_request, "a WebSocket upgrade is a GET");
  if (req.version() < 11) return refuse(http::status::bad_request, "a WebSocket upgrade needs HTTP/1.1");
  if (!has_token(sv(req[http::field::upgrade]), "websocket"))
    return refuse(http::status::bad_request, "Upgrade is not websocket");
  if (!has_token(sv(req[http::field::connection]), "upgrade"))
    return refuse(http::status::bad_request, "Connection does not say upgrade");
  if (sv(req[http::field::sec_websocket_version]) != "13")
    return refuse(http::status::upgrade_required, "Sec-WebSocket-Version must be 13");
  const std::string_view key = sv(req[http::field::sec_websocket_key]);
  if (!valid_key(key)) return refuse(http::status::bad_request, "bad Sec-WebSocket-Key");
  HandshakeResult r;
  r.ok = true;
  r.response =
      "HTTP/1.1 101 Switching Protocols\r\n"
      "Upgrade: websocket\r\n"
      "Connection: Upgrade\r\n"
      "Server: matchcast\r\n"
      "Sec-WebSocket-Accept: " +
      websocket_accept(key) + "\r\n\r\n";
  return r;
}

}  // namespace mc::relay
