// MonitorDecoder: each datagram kind, trailing NULs, and refusals
// (oversized, unknown sizes, garbage).
#include "server/ingest/monitor_decoder.hpp"

#include <gtest/gtest.h>

namespace mc::ingest {
namespace {

using Kind = MonitorDecoder::Kind;

Kind decode(MonitorDecoder& d, std::string_view dg, WorldState& s, MessageRecord& m, std::string& err) {
  return d.decode(dg, s, m, err);
}

TEST(MonitorDecoder, TextKinds) {
  MonitorDecoder d;
  WorldState s;
  MessageRecord m;
  std::string err;
  EXPECT_EQ(decode(d, std::string_view("(server_param (goal_width 14.02))\0", 34), s, m, err), Kind::Params);
  EXPECT_DOUBLE_EQ(d.context().params.goal_width(), 14.02);
  EXPECT_EQ(decode(d, "(player_type (id 1)(player_speed_max 1.05))", s, m, err), Kind::Params);
  EXPECT_EQ(d.context().params.player_types.size(), 2u);
  EXPECT_EQ(decode(d, std::string_view("(msg 0 1 \"(change_player_type l 2 1)\")\0", 39), s, m, err), Kind::Message);
  EXPECT_EQ(m.text, "(change_player_type l 2 1)");
  EXPECT_EQ(decode(d, "(error illegal_client_version)", s, m, err), Kind::Reply);
  EXPECT_EQ(m.text, "(error illegal_client_version)");
  ASSERT_EQ(decode(d, "(show 3 (pm 4) (tm A B 0 0) ((b) 0 0 0 0))", s, m, err), Kind::Show) << err;
  EXPECT_EQ(s.play_mode, PlayMode::KickOffL);
  // A v3-style show without (pm)/(tm) keeps the last ones (mixed-version cache bug).
  ASSERT_EQ(decode(d, "(show 4 ((b) 1 0 0 0))", s, m, err), Kind::Show) << err;
  EXPECT_EQ(s.play_mode, PlayMode::KickOffL);
  EXPECT_EQ(s.left.name, "A");
}

TEST(MonitorDecoder, JsonKinds) {
  MonitorDecoder d;
  WorldState s;
  MessageRecord m;
  std::string err;
  EXPECT_EQ(decode(d, R"({"server_param":{"goal_width":14.02,"auto_mode":true}})", s, m, err), Kind::Params);
  EXPECT_EQ(d.context().params.server.number("auto_mode", 0), 1);
  EXPECT_EQ(decode(d, R"x({"msg":{"time":0,"stime":47,"board":1,"message":"(x)"}})x", s, m, err), Kind::Message);
  ASSERT_EQ(decode(d, R"({"show":{"time":171,"stime":2,"mode":"play_on","team":{"l":{"name":"Alpha","score":0},"r":{"name":"Beta","score":3}},"ball":{"x":-2.1916,"y":-3.0192,"vx":0.877,"vy":0.0307},"players":[]}})", s, m, err),
            Kind::Show) << err;
  EXPECT_EQ(s.right.score, 3);
  EXPECT_EQ(s.play_mode, PlayMode::PlayOn);
  EXPECT_EQ(decode(d, R"({"show":{"time":1}})", s, m, err), Kind::Error);
  EXPECT_EQ(decode(d, R"({"show":)", s, m, err), Kind::Error);
  EXPECT_EQ(decode(d, R"({"version":"19.0.0"})", s, m, err), Kind::Ignored);
}

TEST(MonitorDecoder, Refusals) {
  MonitorDecoder d;
  WorldState s;
  MessageRecord m;
  std::string err;
  EXPECT_EQ(decode(d, std::string(kMaxDatagram + 1, '('), s, m, err), Kind::Error);
  EXPECT_NE(err.find("oversized"), std::string::npos);
  EXPECT_EQ(decode(d, "", s, m, err), Kind::Error);
  EXPECT_EQ(decode(d, std::string(100, '\x07'), s, m, err), Kind::Error);
  EXPECT_EQ(decode(d, "(hello)", s, m, err), Kind::Error);
  std::string bin(2052, '\0');
  bin[1] = 9;  // PPARAM in a v1 datagram: not a v1 record
  EXPECT_EQ(decode(d, bin, s, m, err), Kind::Error);
  bin[1] = 4;  // BLANK
  EXPECT_EQ(decode(d, bin, s, m, err), Kind::Ignored);
}

}  // namespace
}  // namespace mc::ingest
