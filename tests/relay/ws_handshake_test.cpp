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

std::string hex(const std::array<unsigned char, 20>& d) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string s;
  for (unsigned char c : d) (s += kHex[c >> 4]) += kHex[c & 15];
  return s;
}

TEST(WsHandshake, Sha1MatchesFips180Vectors) {
  EXPECT_EQ(hex(sha1("")), "da39a3ee5e6b4b0d3255bfef95601890afd80709");
  EXPECT_EQ(hex(sha1("abc")), "a9993e364706816aba3e25717850c26c9cd0d89d");
  // 56 bytes: the length no longer fits the first padding block.
  EXPECT_EQ(hex(sha1("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq")),
            "84983e441c3bd26ebaae4aa1f95129e5e54670f1");
  EXPECT_EQ(hex(sha1(std::string(1000000, 'a'))), "34aa973cd4c4daa4f61eeb2bdbad27316534016f");
  // 64 bytes: exactly one block before the padding.
  EXPECT_EQ(hex(sha1(std::string(64, 'a'))), "0098ba824b5c16427bd7a1122a5a442a25ec644d");
}

TEST(WsHandshake, Base64PadsAsRfc4648Says) {
  const auto* b = reinterpret_cast<const unsigned char*>("foobar");
  EXPECT_EQ(base64(b, 0), "");
  EXPECT_EQ(base64(b, 1), "Zg==");
  EXPECT_EQ(base64(b, 2), "Zm8=");
  EXPECT_EQ(base64(b, 3), "Zm9v");
  EXPECT_EQ(base64(b, 6), "Zm9vYmFy");
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
