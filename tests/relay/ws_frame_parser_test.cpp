// The load generator's frame splitter against the relay's own frame headers:
// every length class, several frames in one read, partial input, and the
// frames a server must never send.
#include "server/tools/loadgen/ws_frame_parser.hpp"

#include <gtest/gtest.h>

#include "server/relay/message.hpp"

namespace mc::loadgen {
namespace {

TEST(WsFrameParser, ReadsTheRelaysFramesOfEveryLength) {
  for (std::size_t n : {0u, 1u, 125u, 126u, 65535u, 65536u, 70000u}) {
    const auto m = relay::Message::frame(std::string(n, 'x'), false);
    WsFrame f;
    ASSERT_EQ(parse_frame(*m.wire, f), ParseResult::Frame) << n;
    EXPECT_EQ(f.opcode, 2);
    EXPECT_TRUE(f.fin);
    EXPECT_EQ(f.payload.size(), n);
    EXPECT_EQ(f.size, m.wire->size());
    // Any strict prefix is incomplete, never an error.
    for (std::size_t cut : {std::size_t{0}, std::size_t{1}, m.wire->size() / 2, m.wire->size() - 1}) {
      EXPECT_EQ(parse_frame(std::string_view(*m.wire).substr(0, cut), f), ParseResult::NeedMore) << n << " cut " << cut;
    }
  }
}

TEST(WsFrameParser, SplitsSeveralFramesFromOneRead) {
  const auto a = relay::Message::control(R"({"type":"hello"})");
  const auto b = relay::Message::frame("frame", true);
  const std::string both = *a.wire + *b.wire;
  WsFrame f;
  ASSERT_EQ(parse_frame(both, f), ParseResult::Frame);
  EXPECT_EQ(f.opcode, 1);
  EXPECT_EQ(f.payload, R"({"type":"hello"})");
  ASSERT_EQ(parse_frame(std::string_view(both).substr(f.size), f), ParseResult::Frame);
  EXPECT_EQ(f.opcode, 2);
  EXPECT_EQ(f.payload, "frame");
}

TEST(WsFrameParser, RefusesMaskedReservedAndHugeFrames) {
  WsFrame f;
  EXPECT_EQ(parse_frame(std::string("\x82\x81" "abcdx", 7), f), ParseResult::Bad);  // masked
  EXPECT_EQ(parse_frame(std::string("\xC2\x01x", 3), f), ParseResult::Bad);         // RSV1
  const std::string huge("\x82\x7F\x7F\xFF\xFF\xFF\xFF\xFF\xFF\xFF", 10);
  EXPECT_EQ(parse_frame(huge, f), ParseResult::Bad);
}

}  // namespace
}  // namespace mc::loadgen
