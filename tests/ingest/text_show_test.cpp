// parse_text_show: monitor v3/v4/v5 and log forms, optional fields, and
// every truncation of a real show fails cleanly.
#include "server/ingest/text_show.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mc::ingest {
namespace {

// rcss-protocol.md section 3.3, monitor v5 from rcssserver 19.
const std::string kV5 =
    "(show 53 (pm 3) (tm Alpha Beta 0 0) ((b) -37.6726 1.8151 2.8023 -0.0017) ((l 1) 0 0x9 -43.4937 "
    "1.4413 0 0 4.112 90 -58.0505 -5.9321 (v h 60) (fp 6 20) (s 7930 1 1 129970) (f l 2) (c 1 7 44 1 1 5 "
    "1 0 0 2 1 2)) ((l 2) 1 0x1 -37.9577 -20.3104 -0 0 96.582 0 -28.9084 -24.5663 (v h 180) (fp 6 20) (s "
    "8000 0.920331 1 129520) (f l 3) (c 0 18 35 0 1 0 1 0 0 2 1 2)))";

TEST(TextShow, MonitorV5) {
  WorldState s;
  ShowExtras x;
  std::string err;
  ASSERT_TRUE(parse_text_show(kV5, s, x, err)) << err;
  EXPECT_TRUE(x.has_play_mode);
  EXPECT_TRUE(x.has_team);
  EXPECT_EQ(s.time, 53);
  EXPECT_EQ(s.play_mode, PlayMode::PlayOn);
  EXPECT_EQ(s.left.name, "Alpha");
  EXPECT_DOUBLE_EQ(s.ball.vy, -0.0017);
  const PlayerState& g = s.players[0];
  EXPECT_EQ(g.state, 0x9u);
  EXPECT_TRUE(g.goalie());
  ASSERT_TRUE(g.point && g.focus_point && g.capacity && g.attention);
  EXPECT_DOUBLE_EQ((*g.point)[0], -58.0505);
  EXPECT_DOUBLE_EQ((*g.focus_point)[1], 20);
  EXPECT_DOUBLE_EQ(*g.capacity, 129970);
  EXPECT_EQ(g.view_width, 60);
  EXPECT_EQ(g.counters.count, 12);
  EXPECT_EQ(g.counters.dash, 7u);
  EXPECT_EQ(g.counters.change_focus, 2u);
  EXPECT_TRUE(std::signbit(s.players[1].vx));  // "-0"
  // Slots not in the record are absent players, parked.
  EXPECT_EQ(s.players[5].state, 0u);
  EXPECT_EQ(s.players[5].unum, 6);
  EXPECT_DOUBLE_EQ(s.players[5].x, -18);
  EXPECT_DOUBLE_EQ(s.players[5].y, -37);
}

TEST(TextShow, PenaltyScoresInTm) {
  WorldState s;
  ShowExtras x;
  std::string err;
  ASSERT_TRUE(parse_text_show("(show 9000 (pm 48) (tm A null 2 2 4 1 3 2) ((b) 0 0 0 0))", s, x, err)) << err;
  EXPECT_EQ(s.right.name, "");
  EXPECT_EQ(s.left.pen_score, 4);
  EXPECT_EQ(s.right.pen_miss, 2);
  EXPECT_EQ(s.play_mode, PlayMode::PenaltyScoreL);
}

TEST(TextShow, EveryTruncationFailsWithAPosition) {
  WorldState s;
  ShowExtras x;
  std::string err;
  for (std::size_t n = 0; n + 1 < kV5.size(); ++n) {
    err.clear();
    EXPECT_FALSE(parse_text_show(std::string_view(kV5).substr(0, n), s, x, err)) << n;
    EXPECT_NE(err.find("at byte"), std::string::npos) << n;
  }
}

TEST(TextShow, MalformedFieldsAreRejected) {
  WorldState s;
  ShowExtras x;
  std::string err;
  for (const char* bad : {
           "(show 1 ((b) 0 0 0))",                                          // ball short
           "(show 1 ((b) 0 0 0 0) ((l 12) 0 0 0 0 0 0 0 0 (v h 90) (s 1 1 1) (c)))",  // unum
           "(show 1 ((b) 0 0 0 0) ((x 1) 0 0 0 0 0 0 0 0 (v h 90) (s 1 1 1) (c)))",   // side
           "(show 1 ((b) 0 0 0 0) ((l 1) 0 0xZ 0 0 0 0 0 0 (v h 90) (s 1 1 1) (c)))",  // state
           "(show 1 ((b) 0 0 0 0) ((l 1) 0 0 0 0 0 0 0 0 (v q 90) (s 1 1 1) (c)))",   // view
           "(show 1 ((b) 0 0 0 0) ((l 1) 0 0 0 0 0 0 0 0 (v h 90) (zz 1) (c)))",      // unknown
           "(show 1 ((b) 0 0 0 0) ((l 1) 0 0 0 0 0 0 0 0 (c 1 2 3 4 5 6 7 8 9 10 11 12 13)))",
           "(show 1 (pm 99) ((b) 0 0 0 0))",                                // play mode range
           "(show 1 ((b) 0 0 0 0)) trailing",
           "(show x ((b) 0 0 0 0))",
           "(show 1)",                                                      // no ball
       }) {
    EXPECT_FALSE(parse_text_show(bad, s, x, err)) << bad;
  }
}

}  // namespace
}  // namespace mc::ingest
