// The server side of the WebSocket opening handshake (RFC 6455 section 4.2):
// checks an upgrade request and writes the 101 response. Beast parses the
// HTTP request as for every other path; the relay then runs the connection
// itself (websocket_session), so the response is built here, where its
// bytes are visible and tested.
#pragma once

#include <array>
#include <boost/beast/http.hpp>
#include <string>
#include <string_view>

namespace mc::relay {

struct HandshakeResult {
  bool ok = false;
  std::string response;  // ok: the 101 response bytes to send before any frame
  // !ok: the HTTP status to answer with and why (426 asks for version 13).
  boost::beast::http::status status = boost::beast::http::status::bad_request;
  std::string error;
};

// Sec-WebSocket-Accept for a client's Sec-WebSocket-Key: base64(SHA-1(key + GUID)).
std::string websocket_accept(std::string_view client_key);

// SHA-1 (FIPS 180-4) and base64 (RFC 4648), for the accept key only:
// Beast's (boost/beast/core/detail), the code its own websocket handshake
// runs, not OpenSSL's: OpenSSL 3's SHA1() starts its provider machinery on
// first use, which touches ~2 MB of libcrypto's pages, resident for the
// process's life, in a relay that has no other use for libcrypto without TLS.
std::array<unsigned char, 20> sha1(std::string_view data);
std::string base64(const unsigned char* data, std::size_t n);

// Checks `req` (GET, HTTP/1.1, Upgrade: websocket, Connection: upgrade, a
// 16-byte base64 key, version 13). No subprotocol and no extension is
// accepted: the relay sends pre-framed bytes, never deflated.
HandshakeResult accept_upgrade(const boost::beast::http::request<boost::beast::http::string_body>& req);

}  // namespace mc::relay
