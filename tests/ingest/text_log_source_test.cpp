// The ULG4/5/6 text log reader against the real full games and hand-made
// broken inputs.
#include "server/ingest/state_source.hpp"

#include <gtest/gtest.h>

#include <set>

namespace mc::ingest {
namespace {

const std::string kData = std::string(MATCHCAST_TEST_RCG_DIR) + "/";

TEST(TextLogSource, FullUlg6GameMatchesReadme) {
  std::string err;
  auto src = open_log(kData + "full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz", err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  std::uint64_t n = 0;
  int last_time = 0, max_stoppage = 0;
  std::set<PlayMode> modes;
  while (src->next(s)) {
    EXPECT_EQ(s.index, n);
    EXPECT_GE(s.time, last_time);
    last_time = s.time;
    max_stoppage = std::max(max_stoppage, s.stoppage);
    modes.insert(s.play_mode);
    ++n;
  }
  EXPECT_EQ(n, 6689u);
  EXPECT_EQ(src->stats().shows, 6689u);
  EXPECT_EQ(src->stats().skipped, 0u) << (src->stats().errors.empty() ? "" : src->stats().errors[0]);
  EXPECT_EQ(s.time, 6000);
  EXPECT_EQ(s.left.name, "HELIOS_A");
  EXPECT_EQ(s.right.name, "HELIOS_B");
  EXPECT_EQ(s.left.score, 1);
  EXPECT_EQ(s.right.score, 5);
  EXPECT_GE(max_stoppage, 40);  // ~50 shows at each goal time
  EXPECT_TRUE(modes.count(PlayMode::GoalR));
  EXPECT_TRUE(modes.count(PlayMode::FoulChargeL));
  // ULG6: focus point and 12 counters on every player; 18 player types.
  EXPECT_TRUE(s.players[0].focus_point.has_value());
  EXPECT_EQ(s.players[0].counters.count, 12);
  EXPECT_TRUE(s.players[0].capacity.has_value());
  EXPECT_EQ(src->params().player_types.size(), 18u);
  EXPECT_DOUBLE_EQ(src->params().server.number("goal_width", 0), 14.02);
  // The (result ..) message is the last event.
  SourceEvent ev, last;
  bool any = false;
  while (src->poll_event(ev)) {
    last = ev;
    any = true;
  }
  ASSERT_TRUE(any);
  EXPECT_EQ(last.message.text, "(result 202611220304 HELIOS_A_1-vs-HELIOS_B_5)");
}

TEST(TextLogSource, FirstShowFieldsAreExact) {
  std::string err;
  auto src = open_log(kData + "full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz", err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  ASSERT_TRUE(src->next(s));
  EXPECT_EQ(s.index, 0u);
  EXPECT_EQ(s.time, 1);
  EXPECT_EQ(s.stoppage, 0);
  EXPECT_EQ(s.play_mode, PlayMode::KickOffL);
  EXPECT_EQ(s.left.name, "HELIOS_A");
  const PlayerState& g = s.players[0];
  EXPECT_EQ(g.side, Side::Left);
  EXPECT_EQ(g.unum, 1);
  EXPECT_TRUE(g.goalie());
  EXPECT_EQ(s.players[player_index(Side::Right, 11)].unum, 11);
  EXPECT_EQ(s.players[player_index(Side::Right, 11)].side, Side::Right);
}

std::string mini_log(const std::string& body) {
  return "ULG5\n(playmode 1 kick_off_l)\n(team 1 A null 0 0)\n" + body;
}
const char* kShow1 =
    "(show 1 ((b) 0 -0 1e-05 -0) ((l 1) 0 0x9 -49 0 0 0 158.827 0 (v h 180) (s 8000 1 1 130600) "
    "(c 0 0 33 0 1 34 1 0 0 0 0)) ((l 2) 13 0 -6 -37 0 0 0 0 -5.4 -29.5 (v l 90) (s 8000 0.9 1 "
    "130600) (f l 3) (c 0 0 23 0 1 24 1 0 0 0 0)))\n";

TEST(TextLogSource, OptionalFieldsAndQuirks) {
  const std::string log = mini_log(kShow1);
  std::string err;
  auto src = open_log_memory(log, err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  ASSERT_TRUE(src->next(s));
  EXPECT_EQ(s.right.name, "");  // "null"
  EXPECT_DOUBLE_EQ(s.ball.vx, 1e-05);
  const PlayerState& p2 = s.players[1];
  EXPECT_EQ(p2.type, 13);
  EXPECT_EQ(p2.state, 0u);  // bare "0"
  ASSERT_TRUE(p2.point.has_value());
  EXPECT_DOUBLE_EQ((*p2.point)[1], -29.5);
  EXPECT_EQ(p2.view_quality, 'l');
  ASSERT_TRUE(p2.attention.has_value());
  EXPECT_EQ(p2.attention->second, 3);
  EXPECT_FALSE(p2.focus_point.has_value());
  EXPECT_EQ(p2.counters.count, 11);
  // Absent slots are filled as parked players.
  EXPECT_EQ(s.players[player_index(Side::Right, 4)].unum, 4);
  EXPECT_DOUBLE_EQ(s.players[player_index(Side::Right, 4)].x, 12.0);
  EXPECT_DOUBLE_EQ(s.players[player_index(Side::Right, 4)].y, -37.0);
  EXPECT_FALSE(src->next(s));
}

TEST(TextLogSource, RepeatedTimeCountsStoppage) {
  std::string body;
  for (int i = 0; i < 3; ++i) body += kShow1;
  const std::string log = mini_log(body);
  std::string err;
  auto src = open_log_memory(log, err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  int n = 0;
  while (src->next(s)) EXPECT_EQ(s.stoppage, n++);
  EXPECT_EQ(n, 3);
}

TEST(TextLogSource, GarbageLinesAreCountedWithTheirOffset) {
  const std::string bad = "(show 2 ((b) 0 0 0 0) ((l 1) 0 0x9 -49 0\n";
  const std::string log = mini_log(std::string(kShow1) + "garbage here\n" + bad + kShow1 +
                                   "(playmode 5 no_such_mode)\n(msg 5 1 \"unterminated\n");
  std::string err;
  auto src = open_log_memory(log, err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  int n = 0;
  while (src->next(s)) ++n;
  EXPECT_EQ(n, 2);
  EXPECT_EQ(src->stats().skipped, 4u);
  ASSERT_EQ(src->stats().errors.size(), 4u);
  const std::size_t garbage_at = log.find("garbage");
  EXPECT_NE(src->stats().errors[0].find("offset " + std::to_string(garbage_at)), std::string::npos)
      << src->stats().errors[0];
}

TEST(TextLogSource, TruncatedPlainFileYieldsCompleteShows) {
  std::string log = mini_log(std::string(kShow1) + kShow1);
  log.resize(log.size() - 20);  // cut inside the second show
  std::string err;
  auto src = open_log_memory(log, err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  int n = 0;
  while (src->next(s)) ++n;
  EXPECT_EQ(n, 1);
  EXPECT_EQ(src->stats().skipped, 1u);
  // The cut record did not clobber the last good state.
  EXPECT_EQ(s.index, 0u);
  EXPECT_EQ(s.time, 1);
  EXPECT_DOUBLE_EQ(s.players[0].x, -49);
  EXPECT_EQ(s.players[1].type, 13);
}

TEST(TextLogSource, NotALogIsRefused) {
  std::string err;
  EXPECT_FALSE(open_log_memory("hello world\n", err));
  EXPECT_FALSE(err.empty());
  EXPECT_FALSE(open_log_memory("", err));
  EXPECT_FALSE(open_log(kData + "no-such-file.rcg", err));
}

}  // namespace
}  // namespace mc::ingest
