#include "anim/animator.hpp"

#include <cmath>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "synthetic_game.hpp"

namespace mc::anim {
namespace {

using testing::run_game;

std::vector<PoseFrame> animate(const std::vector<WorldState>& game, AnimConfig cfg = {},
                               std::vector<AnimEvent>* events = nullptr) {
  GameParams params;
  Animator a(human_skeleton(), params, cfg);
  std::vector<PoseFrame> out;
  for (const WorldState& s : game) a.push(s, out, events);
  a.finish(out, events);
  return out;
}

TEST(Animator, HoldsBackTheLookAheadThenEmitsTwoFramesPerState) {
  GameParams params;
  Animator a(human_skeleton(), params);
  std::vector<PoseFrame> out;
  const auto game = run_game(10, 0.5);
  a.push(game[0], out);
  a.push(game[1], out);
  EXPECT_TRUE(out.empty());
  a.push(game[2], out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].seq, 0u);
  EXPECT_EQ(out[1].seq, 1u);
  EXPECT_EQ(out[1].substep, 1);
  for (std::size_t i = 3; i < game.size(); ++i) a.push(game[i], out);
  a.finish(out);
  ASSERT_EQ(out.size(), 2 * game.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    EXPECT_EQ(out[i].seq, i);
    EXPECT_EQ(out[i].server_time_ms, 0u);
  }
}

TEST(Animator, RootIsExactAtCyclesAndInterpolatedBetween) {
  const auto game = run_game(40, 0.6);
  const auto out = animate(game);
  for (std::size_t c = 0; c + 1 < game.size(); ++c) {
    const PlayerPose& at = out[2 * c].players[0];
    const PlayerPose& mid = out[2 * c + 1].players[0];
    EXPECT_NEAR(at.x, game[c].players[0].x, 1e-4);
    EXPECT_NEAR(at.y, game[c].players[0].y, 1e-4);
    EXPECT_NEAR(mid.x, 0.5 * (game[c].players[0].x + game[c + 1].players[0].x), 1e-4);
    EXPECT_GT(at.z, 0.6f);
    EXPECT_LT(at.z, 1.01f);
  }
}

TEST(Animator, FillsTheFrameFromTheState) {
  auto game = run_game(6, 0.3);
  game[3].left.score = 2;
  game[3].play_mode = PlayMode::GoalL;
  std::vector<AnimEvent> events;
  const auto out = animate(game, {}, &events);
  const PoseFrame& f = out[6];
  EXPECT_EQ(f.time, game[3].time);
  EXPECT_EQ(f.play_mode, PlayMode::GoalL);
  EXPECT_EQ(f.score_left, 2);
  EXPECT_NEAR(f.ball.z, 0.085f, 1e-6f);
  EXPECT_EQ(f.players[12].side, Side::Right);
  EXPECT_EQ(f.players[12].unum, 2);
  bool goal = false, mode = false;
  for (const AnimEvent& e : events) {
    goal |= e.type == AnimEventType::Goal && e.side == Side::Left && e.seq == 6;
    mode |= e.type == AnimEventType::PlayMode && e.play_mode == PlayMode::GoalL;
  }
  EXPECT_TRUE(goal);
  EXPECT_TRUE(mode);
}

TEST(Animator, HeadFollowsTheServerNeckAngleAtCycles) {
  auto game = run_game(20, 0.0);
  for (std::size_t i = 0; i < game.size(); ++i) game[i].players[0].neck = i % 2 ? 60 : -30;
  const auto out = animate(game);
  for (std::size_t c = 2; c + 2 < game.size(); ++c) {
    const auto& a = out[2 * c].players[0].angles;
    const float yaw = a[dof::kPelvis] + a[dof::kTorso] + a[dof::kNeck] + a[dof::kHead];
    EXPECT_NEAR(-yaw, game[c].players[0].neck, 0.01) << c;  // body yaw is +left, neck +right
  }
}

TEST(Animator, EqualInputGivesByteEqualOutput) {
  const auto game = run_game(60, 0.8);
  const auto a = animate(game);
  const auto b = animate(game);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(PoseFrame)), 0);
}

TEST(Animator, LegsSwingWhenRunningAndRestWhenStanding) {
  const auto out = animate(run_game(60, 0.7));
  float lo = 1e9f, hi = -1e9f;
  for (std::size_t f = 40; f < 100; ++f) {
    lo = std::min(lo, out[f].players[0].angles[dof::kRHip]);
    hi = std::max(hi, out[f].players[0].angles[dof::kRHip]);
  }
  EXPECT_GT(hi - lo, 30.0f);
  // A standing player (left 2) keeps still.
  EXPECT_NEAR(out[50].players[1].angles[dof::kRHip], out[90].players[1].angles[dof::kRHip], 1e-4f);
}

}  // namespace
}  // namespace mc::anim
