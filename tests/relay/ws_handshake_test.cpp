#include "server/relay/ws_handshake.hpp"

#include <gtest/gtest.h>

namespace http = boost::beast::http;

namespace mc::relay {
namespace {

http::request<http::string_body> upgrade_request() {
  http::request<http::string_body> req{http::verb::get, "/ws", 11};
  req.set(http::field::host, "127.0.0.1");
  req.set(http::field::upgrade, "websocket");
  req.set(http::field::connection, "keep-alive, Upgrade");
  req.set(http::field::sec_websocket_key, "dGhlIHNhbXBsZSBub25jZQ==");
  req.set(http::field::sec_websocket_version, "13");
  return req;
}

TEST(WsHandshake, AcceptKeyIsRfc6455s) {
  // RFC 6455 section 1.3's worked example.
  EXPECT_EQ(websocket_accept("dGhlIHNhbXBsZSBub25jZQ=="), "s3pPLMBiTxaQ9kYGzzhZRbK+xOo=");
}

TEST(WsHandshake, AnswersAValidUpgradeWith101) {
  const auto r = accept_upgrade(upgrade_request());
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.response.rfind("HTTP/1.1 101 Switching Protocols\r\n", 0), 0u);
  EXPECT_NE(r.response.find("Sec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo=\r\n"), std::string::npos);
  EXPECT_NE(r.response.find("Upgrade: websocket\r\n"), std::string::npos);
  EXPECT_EQ(r.response.substr(r.response.size() - 4), "\r\n\r\n");
  // No extension is ever agreed: the relay's frames are pre-built, never deflated.
  EXPECT_EQ(r.response.find("Extensions"), std::string::npos);
}

TEST(WsHandshake, RefusesBrokenUpgradesWithTheRightStatus) {
  auto version = upgrade_request();
  version.set(http::field::sec_websocket_version, "8");
  EXPECT_EQ(accept_upgrade(version).status, http::status::upgrade_required);
  auto key = upgrade_request();
  key.set(http::field::sec_websocket_key, "short");
  EXPECT_FALSE(accept_upgrade(key).ok);
  auto post = upgrade_request();
  post.method(http::verb::post);
  EXPECT_FALSE(accept_upgrade(post).ok);
  auto old = upgrade_request();
  old.version(10);
  EXPECT_FALSE(accept_upgrade(old).ok);
  auto conn = upgrade_request();
  conn.set(http::field::connection, "close");
  const auto r = accept_upgrade(conn);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.status, http::status::bad_request);
  EXPECT_FALSE(r.error.empty());
}

}  // namespace
}  // namespace mc::relay
