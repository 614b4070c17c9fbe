// The non-show text records: playmode, team, msg (unescaped quotes),
// server/player params and player types.
#include "server/ingest/text_records.hpp"

#include <gtest/gtest.h>

namespace mc::ingest {
namespace {

TEST(TextRecords, PlayMode) {
  int t = 0;
  PlayMode pm{};
  std::string err;
  ASSERT_TRUE(parse_playmode_record("(playmode 380 foul_charge_r)", t, pm, err)) << err;
  EXPECT_EQ(t, 380);
  EXPECT_EQ(pm, PlayMode::FoulChargeR);
  EXPECT_FALSE(parse_playmode_record("(playmode 1 nonsense)", t, pm, err));
  EXPECT_FALSE(parse_playmode_record("(playmode 1 play_on", t, pm, err));
}

TEST(TextRecords, TeamWithAndWithoutPenalties) {
  int t = 0;
  TeamInfo l, r;
  std::string err;
  ASSERT_TRUE(parse_team_record("(team 216 HELIOS_base kn2c 0 1)", t, l, r, err)) << err;
  EXPECT_EQ(l.name, "HELIOS_base");
  EXPECT_EQ(r.score, 1);
  ASSERT_TRUE(parse_team_record("(team 8000 A null 1 1 3 2 4 1)", t, l, r, err)) << err;
  EXPECT_EQ(r.name, "");
  EXPECT_EQ(r.pen_score, 4);
  EXPECT_FALSE(parse_team_record("(team 1 A B 1)", t, l, r, err));
}

TEST(TextRecords, MsgKeepsUnescapedQuotes) {
  MessageRecord m;
  std::string err;
  ASSERT_TRUE(parse_msg_record(R"x((msg 0 1 "(team_graphic_l (0 0 "8 8 1 1" "a c #ff0000"))"))x", m, err)) << err;
  EXPECT_EQ(m.time, 0);
  EXPECT_EQ(m.board, 1);
  EXPECT_EQ(m.text, R"x((team_graphic_l (0 0 "8 8 1 1" "a c #ff0000")))x");
  ASSERT_TRUE(parse_msg_record(R"x((msg 940 1 "(result 201909260749 HELIOS_base_0-vs-kn2c_4)"))x", m, err));
  EXPECT_EQ(m.text, "(result 201909260749 HELIOS_base_0-vs-kn2c_4)");
  EXPECT_FALSE(parse_msg_record(R"x((msg 1 1 "open)x", m, err));
  EXPECT_FALSE(parse_msg_record(R"((msg 1 1 noquote))", m, err));
}

TEST(TextRecords, ParamsWithQuotedStrings) {
  ParamTable t;
  std::string err;
  ASSERT_TRUE(parse_param_record(
      R"x((server_param (goal_width 14.02)(log_date_format "%Y%m%d%H%M%S-")(coach_msg_file "")(half_time 300)))x",
      "server_param", t, err))
      << err;
  EXPECT_DOUBLE_EQ(t.number("goal_width", 0), 14.02);
  EXPECT_EQ(t.text("log_date_format"), "%Y%m%d%H%M%S-");
  EXPECT_EQ(t.text("coach_msg_file"), "");
  EXPECT_FALSE(parse_param_record("(server_param (a 1)(b \"x)", "server_param", t, err));
  EXPECT_FALSE(parse_param_record("(player_param (a 1))", "server_param", t, err));
}

TEST(TextRecords, PlayerTypes) {
  GameParams p;
  std::string err;
  ASSERT_TRUE(parse_player_type_record(
      "(player_type (id 3)(player_speed_max 1.05)(player_decay 0.377766)(kickable_margin 0.75)(player_size 0.3)"
      "(unum_far_length 20))",
      p, err))
      << err;
  ASSERT_EQ(p.player_types.size(), 4u);
  EXPECT_EQ(p.player_types[1].id, 1);  // filled with defaults
  EXPECT_DOUBLE_EQ(p.type(3).player_decay, 0.377766);
  EXPECT_DOUBLE_EQ(p.type(3).kickable_distance(), 0.3 + 0.75 + 0.085);
  EXPECT_FALSE(parse_player_type_record("(player_type (id 999))", p, err));
  EXPECT_FALSE(parse_player_type_record("(player_type (player_decay 1))", p, err));
}

}  // namespace
}  // namespace mc::ingest
