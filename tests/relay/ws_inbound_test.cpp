#include "server/relay/ws_inbound.hpp"

#include <gtest/gtest.h>

#include <string>

namespace mc::relay {
namespace {

// A client frame: FIN/opcode, masked with `key`, any length class.
std::string client_frame(std::uint8_t opcode, std::string_view payload, bool fin = true,
                         std::string key = std::string("\x11\x22\x33\x44", 4), bool masked = true) {
  std::string f;
  f.push_back(static_cast<char>((fin ? 0x80 : 0) | opcode));
  const std::size_t n = payload.size();
  const char mask_bit = masked ? static_cast<char>(0x80) : 0;
  if (n < 126) {
    f.push_back(static_cast<char>(mask_bit | static_cast<char>(n)));
  } else if (n <= 0xFFFF) {
    f.push_back(static_cast<char>(mask_bit | 126));
    f.push_back(static_cast<char>(n >> 8));
    f.push_back(static_cast<char>(n & 0xFF));
  } else {
    f.push_back(static_cast<char>(mask_bit | 127));
    for (int s = 56; s >= 0; s -= 8) f.push_back(static_cast<char>((static_cast<std::uint64_t>(n) >> s) & 0xFF));
  }
  if (masked) f += key;
  for (std::size_t i = 0; i < n; ++i) f.push_back(masked ? static_cast<char>(payload[i] ^ key[i & 3]) : payload[i]);
  return f;
}

TEST(WsInbound, ReadsTextAndBinaryOfEveryLengthClassByteByByte) {
  WsInbound in(1 << 20);
  const std::string big(70000, 'b'), mid(300, 'm');
  const std::string bytes = client_frame(1, R"({"type":"x"})") + client_frame(2, mid) + client_frame(2, big);
  std::vector<std::string> got;
  WsInbound::Event ev;
  for (char c : bytes) {  // any split of the stream gives the same messages
    in.feed(std::string_view(&c, 1));
    while (in.next(ev)) got.emplace_back(ev.data);
  }
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0], R"({"type":"x"})");
  EXPECT_EQ(got[1], mid);
  EXPECT_EQ(got[2], big);
  EXPECT_EQ(in.buffered(), 0u);
}

TEST(WsInbound, ReassemblesFragmentsAroundControlFrames) {
  WsInbound in(1024);
  in.feed(client_frame(1, "hel", false) + client_frame(9, "p") + client_frame(0, "lo", true) +
          client_frame(8, std::string("\x03\xE8", 2) + "bye"));
  WsInbound::Event ev;
  ASSERT_TRUE(in.next(ev));
  EXPECT_EQ(ev.kind, WsInbound::Kind::Ping);
  EXPECT_EQ(ev.data, "p");
  ASSERT_TRUE(in.next(ev));
  EXPECT_EQ(ev.kind, WsInbound::Kind::Text);
  EXPECT_EQ(ev.data, "hello");
  ASSERT_TRUE(in.next(ev));
  EXPECT_EQ(ev.kind, WsInbound::Kind::Close);
  EXPECT_EQ(ev.code, 1000);
  EXPECT_EQ(ev.data, "bye");
  EXPECT_FALSE(in.next(ev));
}

// Each hostile or broken input gets its close code, and the reader stops.
TEST(WsInbound, RefusesWhatNoSpectatorSends) {
  struct Case {
    std::string bytes;
    CloseCode code;
  };
  const Case cases[] = {
      {client_frame(1, "x", true, "abcd", false), CloseCode::ProtocolError},       // unmasked
      {std::string("\xC1\x81", 2) + "abcd" + "x", CloseCode::ProtocolError},       // RSV1 (deflate) set
      {client_frame(3, "x"), CloseCode::ProtocolError},                            // reserved opcode
      {client_frame(9, "x", false), CloseCode::ProtocolError},                     // fragmented ping
      {client_frame(9, std::string(126, 'p')), CloseCode::ProtocolError},          // control over 125
      {client_frame(0, "x"), CloseCode::ProtocolError},                            // continuation of nothing
      {client_frame(1, "a", false) + client_frame(1, "b"), CloseCode::ProtocolError},  // message inside message
      {client_frame(8, "x"), CloseCode::ProtocolError},                            // 1-byte close payload
      {client_frame(1, std::string(2000, 'x')), CloseCode::TooBig},
      {client_frame(1, std::string(600, 'x'), false) + client_frame(0, std::string(600, 'x')), CloseCode::TooBig},
      // 2^63 - 1 bytes announced: refused from the header, nothing allocated.
      {std::string("\x82\xFF\x7F\xFF\xFF\xFF\xFF\xFF\xFF\xFF", 10), CloseCode::TooBig},
      {std::string("\x82\xFF\xFF\xFF\xFF\xFF\xFF\xFF\xFF\xFF", 10), CloseCode::ProtocolError},
  };
  for (const auto& c : cases) {
    WsInbound in(1024);
    in.feed(c.bytes);
    WsInbound::Event ev;
    ASSERT_TRUE(in.next(ev));
    EXPECT_EQ(ev.kind, WsInbound::Kind::Error);
    EXPECT_EQ(ev.code, static_cast<std::uint16_t>(c.code)) << ev.data;
    EXPECT_FALSE(ev.data.empty());
    in.feed(client_frame(1, "after"));
    EXPECT_FALSE(in.next(ev));  // nothing after an error
  }
}

TEST(WsInbound, ShrinkFreesAnIdleReader) {
  WsInbound in(1 << 20);
  in.feed(client_frame(2, std::string(50000, 'z')));
  WsInbound::Event ev;
  ASSERT_TRUE(in.next(ev));
  in.shrink();
  EXPECT_EQ(in.buffered(), 0u);
  in.feed(client_frame(1, "ok"));
  ASSERT_TRUE(in.next(ev));
  EXPECT_EQ(ev.data, "ok");
}

}  // namespace
}  // namespace mc::relay
