#include "server/relay/ws_handshake.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>

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
  std::uint32_t h[5] = {0x67452301, 0xEFCDAB89, 0x98BADCFE, 0x10325476, 0xC3D2E1F0};
  auto block = [&h](const unsigned char* p) {
    std::uint32_t w[80];
    for (int i = 0; i < 16; ++i)
      w[i] = std::uint32_t{p[4 * i]} << 24 | std::uint32_t{p[4 * i + 1]} << 16 | std::uint32_t{p[4 * i + 2]} << 8 |
             std::uint32_t{p[4 * i + 3]};
    for (int i = 16; i < 80; ++i) w[i] = std::rotl(w[i - 3] ^ w[i - 8] ^ w[i - 14] ^ w[i - 16], 1);
    std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4];
    for (int i = 0; i < 80; ++i) {
      std::uint32_t f, k;
      if (i < 20) f = (b & c) | (~b & d), k = 0x5A827999;
      else if (i < 40) f = b ^ c ^ d, k = 0x6ED9EBA1;
      else if (i < 60) f = (b & c) | (b & d) | (c & d), k = 0x8F1BBCDC;
      else f = b ^ c ^ d, k = 0xCA62C1D6;
      const std::uint32_t t = std::rotl(a, 5) + f + e + k + w[i];
      e = d, d = c, c = std::rotl(b, 30), b = a, a = t;
    }
    h[0] += a, h[1] += b, h[2] += c, h[3] += d, h[4] += e;
  };
  const auto* p = reinterpret_cast<const unsigned char*>(data.data());
  std::size_t n = data.size();
  const std::uint64_t bits = std::uint64_t{n} * 8;
  for (; n >= 64; n -= 64, p += 64) block(p);
  // The tail, the 0x80 marker and the length in bits: one or two blocks.
  unsigned char last[128] = {};
  std::copy(p, p + n, last);
  last[n] = 0x80;
  const std::size_t end = n < 56 ? 64 : 128;
  for (int i = 0; i < 8; ++i) last[end - 1 - i] = static_cast<unsigned char>(bits >> (8 * i));
  for (std::size_t at = 0; at < end; at += 64) block(last + at);
  std::array<unsigned char, 20> out;
  for (int i = 0; i < 20; ++i) out[i] = static_cast<unsigned char>(h[i / 4] >> (24 - 8 * (i % 4)));
  return out;
}

std::string base64(const unsigned char* data, std::size_t n) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve(4 * ((n + 2) / 3));
  for (std::size_t i = 0; i < n; i += 3) {
    const std::uint32_t v = std::uint32_t{data[i]} << 16 | (i + 1 < n ? std::uint32_t{data[i + 1]} << 8 : 0) |
                            (i + 2 < n ? std::uint32_t{data[i + 2]} : 0);
    out.push_back(kAlphabet[v >> 18 & 63]);
    out.push_back(kAlphabet[v >> 12 & 63]);
    out.push_back(i + 1 < n ? kAlphabet[v >> 6 & 63] : '=');
    out.push_back(i + 2 < n ? kAlphabet[v & 63] : '=');
  }
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
