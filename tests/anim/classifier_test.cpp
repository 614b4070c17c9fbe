#include "anim/classifier.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "server/ingest/state_source.hpp"
#include "synthetic_game.hpp"

namespace mc::anim {
namespace {

Action classify_at(const std::vector<WorldState>& g, std::size_t pos, int slot, const GameParams& params) {
  const auto i = static_cast<std::size_t>(slot);
  ClassifyInput in;
  in.cur = &g[pos].players[i];
  in.prev = pos > 0 ? &g[pos - 1].players[i] : nullptr;
  in.next = pos + 1 < g.size() ? &g[pos + 1].players[i] : nullptr;
  in.ball = &g[pos].ball;
  in.type = &params.type(g[pos].players[i].type);
  return classify_raw(in);
}

TEST(SmoothAction, OneNoisyCycleDoesNotFlipTheDecision) {
  const std::vector<Action> w{Action::Walk, Action::Run, Action::Walk};
  EXPECT_EQ(smooth_action(w, 1), Action::Walk);
  // Two cycles of running are a change, not noise.
  const std::vector<Action> two{Action::Walk, Action::Run, Action::Run};
  EXPECT_EQ(smooth_action(two, 1), Action::Run);
  // Events come from state bits and are never smoothed away.
  const std::vector<Action> k{Action::Walk, Action::Kick, Action::Walk};
  EXPECT_EQ(smooth_action(k, 1), Action::Kick);
  // Neighbours that are events do not overrule locomotion.
  const std::vector<Action> e{Action::Kick, Action::Run, Action::Kick};
  EXPECT_EQ(smooth_action(e, 1), Action::Run);
  EXPECT_EQ(smooth_action(w, 0), Action::Walk);
}

TEST(ClassifyRaw, SyntheticLocomotion) {
  GameParams params;
  auto g = testing::run_game(12, 0.8, 0);
  EXPECT_EQ(classify_at(g, 5, 0, params), Action::Run);
  g = testing::run_game(12, 0.1, 0);
  EXPECT_EQ(classify_at(g, 5, 0, params), Action::Walk);
  EXPECT_EQ(classify_at(g, 5, 1, params), Action::Stand);  // a parked team-mate
  // Moving against the body: backpedal; across it: side-step.
  for (auto& s : g) s.players[0].body = 180;
  EXPECT_EQ(classify_at(g, 5, 0, params), Action::Backpedal);
  for (auto& s : g) s.players[0].body = 90;
  EXPECT_EQ(classify_at(g, 5, 0, params), Action::SideStep);
  // Standing and turning.
  g = testing::run_game(12, 0.0, 0);
  for (std::size_t i = 0; i < g.size(); ++i) g[i].players[0].body = 30.0 * static_cast<double>(i);
  EXPECT_EQ(classify_at(g, 5, 0, params), Action::Turn);
}

TEST(ClassifyRaw, StateBitsAndTeleports) {
  GameParams params;
  auto g = testing::run_game(12, 0.3, 0);
  g[5].players[0].state |= state_bits::kKick;
  EXPECT_EQ(classify_at(g, 5, 0, params), Action::Kick);
  g[5].players[0].state |= state_bits::kKickFault;  // a missed kick is not a kick
  EXPECT_NE(classify_at(g, 5, 0, params), Action::Kick);
  // With counters, the kick bit needs a new kick command.
  g[5].players[0].state = state_bits::kStand | state_bits::kKick;
  g[4].players[0].counters.count = g[5].players[0].counters.count = 11;
  g[4].players[0].counters.kick = g[5].players[0].counters.kick = 7;
  EXPECT_NE(classify_at(g, 5, 0, params), Action::Kick);
  g[5].players[0].counters.kick = 8;
  EXPECT_EQ(classify_at(g, 5, 0, params), Action::Kick);
  g[6].players[0].state |= state_bits::kTackle;
  EXPECT_EQ(classify_at(g, 6, 0, params), Action::Tackle);
  g[7].players[0].x += 20;
  EXPECT_EQ(classify_at(g, 7, 0, params), Action::Teleport);
  g[8].players[0].state = 0;
  EXPECT_EQ(classify_at(g, 8, 0, params), Action::Disconnected);
  // A goalie catching beside the body dives.
  g[9].players[0].state = state_bits::kStand | state_bits::kGoalie | state_bits::kCatch;
  g[9].ball.x = g[9].players[0].x + 0.2;
  g[9].ball.y = g[9].players[0].y;
  EXPECT_EQ(classify_at(g, 9, 0, params), Action::Catch);
  g[9].ball.y = g[9].players[0].y + 1.1;  // body faces +x: +y is its right
  EXPECT_EQ(classify_at(g, 9, 0, params), Action::Dive);
}

// Snippets of a real game (rcssserver 19, helios-base): positions in the
// stream found by hand, each checked against its state bits first.
TEST(ClassifyRaw, SnippetsOfARealLog) {
  const std::string path =
      std::string(MATCHCAST_TEST_RCG_DIR) + "/full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";
  std::string err;
  auto src = ingest::open_log(path, err);
  ASSERT_TRUE(src) << err;
  std::vector<WorldState> g;
  WorldState s;
  while (g.size() < 1830 && src->next(s)) g.push_back(s);
  ASSERT_EQ(g.size(), 1830u);
  const GameParams& params = src->params();
  struct Case { std::size_t pos; Side side; int unum; std::uint32_t bits; Action want; };
  const Case cases[] = {
      {3, Side::Left, 3, 0x1, Action::Run},        // 0.89 m/cycle along the body
      {6, Side::Right, 1, 0x9, Action::Stand},     // the goalie waits
      {22, Side::Left, 11, 0x1, Action::Walk},     // 0.12 m/cycle
      {17, Side::Right, 7, 0x1, Action::SideStep}, // moving 106 deg off the body
      {302, Side::Right, 6, 0x1, Action::Backpedal},
      {36, Side::Left, 11, 0x3, Action::Kick},
      {38, Side::Left, 11, 0x1441, Action::Tackle},
      {780, Side::Left, 2, 0x1, Action::Teleport}, // moved 14 m by the referee
      {1821, Side::Right, 1, 0x19, Action::Catch}, // a successful goalie catch
  };
  for (const Case& c : cases) {
    const int slot = player_index(c.side, c.unum);
    ASSERT_EQ(g[c.pos].players[static_cast<std::size_t>(slot)].state, c.bits) << "stream position " << c.pos;
    EXPECT_EQ(classify_at(g, c.pos, slot, params), c.want) << "stream position " << c.pos << ": got "
                                                          << action_name(classify_at(g, c.pos, slot, params));
  }
  // Over the snippet, smoothing leaves no isolated single-cycle locomotion flip.
  int flips = 0;
  const int slot = player_index(Side::Left, 7);
  std::vector<Action> raw;
  for (std::size_t p = 1; p + 1 < 600; ++p) raw.push_back(classify_at(g, p, slot, params));
  for (std::size_t i = 1; i + 1 < raw.size(); ++i) {
    const Action a = smooth_action(raw, i), l = smooth_action(raw, i - 1),
                 r = smooth_action(raw, i + 1);
    if (is_locomotion(a) && is_locomotion(l) && l == r && a != l) ++flips;
  }
  EXPECT_EQ(flips, 0);
}

}  // namespace
}  // namespace mc::anim
