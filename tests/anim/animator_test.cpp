#include "anim/animator.hpp"
#include "anim/player_animation.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "synthetic_game.hpp"

// Counts heap allocations while `g_counting` is set (replaces the global
// operator new of this test executable).
namespace {
bool g_counting = false;
long g_allocations = 0;
}  // namespace
void* operator new(std::size_t n) {
  if (g_counting) ++g_allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace mc::anim {
namespace {

using testing::run_game;

std::vector<WorldState> kick_game(int k, int k2 = -1);
std::vector<WorldState> kick_game_for_alloc() {
  auto g = kick_game(20);
  g[30].play_mode = PlayMode::GoalL;  // and a play-mode event
  return g;
}

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

TEST(Animator, HeadFollowsTheServerNeckAngleAtAHumanSpeed) {
  // The server's neck flips between -30 and 60 deg every cycle for a while,
  // then settles: the head turns towards it at most kMaxUpperStepDeg per
  // joint and frame (issue 23: no pops), and then looks where the server says.
  auto game = run_game(40, 0.0);
  for (std::size_t i = 0; i < game.size(); ++i) game[i].players[0].neck = i < 12 ? (i % 2 ? 60 : -30) : 45;
  const auto out = animate(game);
  for (std::size_t f = 1; f < out.size(); ++f)
    for (int d : {dof::kNeck, dof::kHead})
      EXPECT_LE(std::fabs(out[f].players[0].angles[static_cast<std::size_t>(d)] -
                          out[f - 1].players[0].angles[static_cast<std::size_t>(d)]),
                kMaxUpperStepDeg + 0.01f)
          << f;
  for (std::size_t c = 26; c + 2 < game.size(); ++c) {
    const auto& a = out[2 * c].players[0].angles;
    const float yaw = a[dof::kPelvis] + a[dof::kTorso] + a[dof::kNeck] + a[dof::kHead];
    EXPECT_NEAR(-yaw, game[c].players[0].neck, 0.5) << c;  // body yaw is +left, neck +right
  }
}

TEST(Animator, DoesNotAllocateBeyondTheOutputVectors) {
  auto game = kick_game_for_alloc();
  GameParams params;
  Animator a(human_skeleton(), params);
  std::vector<PoseFrame> out;
  std::vector<AnimEvent> events;
  out.reserve(2 * game.size());
  events.reserve(64);
  g_allocations = 0;
  g_counting = true;
  for (const WorldState& s : game) a.push(s, out, &events);
  a.finish(out, &events);
  g_counting = false;
  EXPECT_EQ(g_allocations, 0);
  EXPECT_EQ(out.size(), 2 * game.size());
  EXPECT_FALSE(events.empty());
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

// A walk up to the ball and a kick at cycle `k` (and `k2` if given) by left
// 1: the ball lies 0.6 m ahead of the player until a kick, then flies off at
// 2 m/cycle; before a second kick it is back at the player's feet.
std::vector<WorldState> kick_game(int k, int k2) {
  auto g = run_game(40, 0.2, 0);
  double ball_x = g[0].players[0].x + 0.6;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const int c = static_cast<int>(i);
    const bool flying = (c >= k && (k2 < 0 || c < k2 - 3)) || (k2 >= 0 && c >= k2);
    ball_x = flying ? ball_x + 2.0 : g[i].players[0].x + 0.6;
    if (k2 >= 0 && k2 - k == 1 && c == k2) ball_x += 0.5;  // the second touch pushes it on
    g[i].ball.x = ball_x;
    g[i].ball.y = 0.15;
  }
  g[static_cast<std::size_t>(k)].players[0].state |= state_bits::kKick;
  if (k2 >= 0) g[static_cast<std::size_t>(k2)].players[0].state |= state_bits::kKick;
  return g;
}

glm::vec3 strike_point(const PlayerPose& p, int foot_joint) {
  const SkeletonDef& s = human_skeleton();
  std::vector<glm::mat4> m(s.joints.size());
  LocalToModelJob fk{&s, std::span<const float>(p.angles.data(), p.angles.size()), glm::vec3(0, p.z, 0), m};
  fk.Run();
  const glm::vec3 b(m[static_cast<std::size_t>(foot_joint)] * glm::vec4(0.19f, -0.04f, 0, 1));
  const BodyFrame body(p.x, p.y, p.heading);
  float fx, fy;
  body.to_field(b.x, b.z, fx, fy);
  return {fx, fy, b.y};
}

TEST(Animator, KickContactFallsBetweenCyclesWithTheFootOnTheBall) {
  const int k = 20;
  const auto game = kick_game(k);
  std::vector<AnimEvent> events;
  const auto out = animate(game, {}, &events);
  const AnimEvent* kick = nullptr;
  for (const AnimEvent& e : events)
    if (e.type == AnimEventType::Kick) kick = &e;
  ASSERT_NE(kick, nullptr);
  EXPECT_EQ(kick->seq, static_cast<std::uint32_t>(2 * (k - 1) + 1));  // half-way into cycle k-1
  EXPECT_EQ(kick->contact_time_ms, kick->seq * 50u);
  EXPECT_EQ(kick->side, Side::Left);
  EXPECT_EQ(kick->unum, 1);
  const PoseFrame& f = out[kick->seq];
  // The ball still waits where it was kicked from...
  EXPECT_NEAR(f.ball.x, game[static_cast<std::size_t>(k - 1)].ball.x, 1e-5);
  // ...and the front of the kicking foot touches it.
  const glm::vec3 s = strike_point(f.players[0], kick->foot == Foot::Right ? kRFoot : kLFoot);
  const float d = std::sqrt((s.x - f.ball.x) * (s.x - f.ball.x) + (s.y - f.ball.y) * (s.y - f.ball.y) +
                            (s.z - f.ball.z) * (s.z - f.ball.z));
  EXPECT_NEAR(d, 0.085f, 0.05f);
  // The root is still exact at the cycles around the contact.
  EXPECT_NEAR(out[kick->seq - 1].players[0].x, game[static_cast<std::size_t>(k - 1)].players[0].x, 1e-4);
  EXPECT_NEAR(out[kick->seq + 1].players[0].x, game[static_cast<std::size_t>(k)].players[0].x, 1e-4);
}

TEST(Animator, KicksInConsecutiveCyclesAreOneKick) {
  std::vector<AnimEvent> events;
  animate(kick_game(20, 21), {}, &events);
  int kicks = 0;
  for (const AnimEvent& e : events) kicks += e.type == AnimEventType::Kick;
  EXPECT_EQ(kicks, 1);
  // ...whose follow-through lasts longer than a single kick's.
  auto action_frames = [](const std::vector<WorldState>& g) {
    GameParams params;
    Animator a(human_skeleton(), params);
    std::vector<FrameInfo> infos;
    a.set_frame_info_sink(&infos);
    std::vector<PoseFrame> out;
    for (const WorldState& s : g) a.push(s, out);
    a.finish(out);
    int n = 0;
    for (const FrameInfo& f : infos) n += f.players[0].in_action;
    return n;
  };
  EXPECT_EQ(action_frames(kick_game(20, 21)), action_frames(kick_game(20)) + 2);
  events.clear();
  animate(kick_game(20, 26), {}, &events);
  kicks = 0;
  for (const AnimEvent& e : events) kicks += e.type == AnimEventType::Kick;
  EXPECT_EQ(kicks, 2);
}

// A tackler the server lets run again: left 1 tackles at cycle 20 (the bit
// on that cycle only), then sprints off at 0.9 m a cycle from cycle 23. He
// gets up within the tackle's 0.3 s blend-out of starting to run, not at the
// end of tackle_cycles (1 s): the slide's pose must not glide along with the
// sprinter (issue 23: up to 9.6 m/s of "grounded foot" in a real game).
TEST(Animator, ATacklerWhoRunsOffGetsUp) {
  const int k = 20, run_from = 23;
  auto game = run_game(60, 0.0, 100);
  double x = game[0].players[0].x;
  for (std::size_t i = 0; i < game.size(); ++i) {
    const int c = static_cast<int>(i);
    if (c >= run_from) x += 0.9;
    game[i].players[0].x = x;
    game[i].players[0].vx = c >= run_from ? 0.9 : 0.0;
    game[i].ball.x = c < k ? x + 0.6 : game[0].players[0].x + 3.0;
    game[i].ball.y = 0.0;
  }
  game[static_cast<std::size_t>(k)].players[0].state |= state_bits::kTackle;
  const testing::AnimatedGame g = testing::animate_game(game);
  // Down in the slide just after the tackle...
  const auto at = [&](int cycle) { return static_cast<std::size_t>(2 * cycle); };
  EXPECT_LT(g.frames[at(k + 1)].players[0].z, 0.6f);
  EXPECT_TRUE(g.infos[at(k + 1)].players[0].in_action);
  // ...and up, running, 0.4 s after he starts to run (tackle_cycles would
  // hold the slide until cycle 30).
  const int up = run_from + 4;
  EXPECT_FALSE(g.infos[at(up)].players[0].in_action);
  EXPECT_GT(g.frames[at(up)].players[0].z, 0.8f);
}

TEST(Animator, DetailLevelsSwitchRunningAndKicking) {
  AnimConfig none;
  none.detail = DetailLevel::None;
  const auto still = animate(run_game(60, 0.7), none);
  EXPECT_NEAR(still[50].players[0].angles[dof::kRHip], still[90].players[0].angles[dof::kRHip], 1e-4f);
  // Kicks only: no kick motion under Run.
  AnimConfig run;
  run.detail = DetailLevel::Run;
  const auto game = kick_game(20);
  const auto a = animate(game, run);
  const auto b = animate(game);
  EXPECT_NE(a[39].ball.x, b[39].ball.x);  // the ball waits at the foot only when kicks are animated
  EXPECT_NE(a[39].players[0].z, b[39].players[0].z);  // the full level crouches into the kick
}

TEST(Animator, LookAheadIsConfigurable) {
  GameParams params;
  AnimConfig cfg;
  cfg.lookahead_cycles = 4;
  Animator a(human_skeleton(), params, cfg);
  std::vector<PoseFrame> out;
  const auto game = run_game(10, 0.5);
  for (int i = 0; i < 4; ++i) a.push(game[static_cast<std::size_t>(i)], out);
  EXPECT_TRUE(out.empty());
  a.push(game[4], out);
  EXPECT_EQ(out.size(), 2u);
}

TEST(Animator, TeleportsJumpAtTheCycleAndDisconnectedPlayersStand) {
  auto game = run_game(30, 0.3);
  for (std::size_t i = 15; i < game.size(); ++i) game[i].players[0].x = 20;  // moved by the referee
  for (auto& s : game) { s.players[5].state = 0; s.players[5].x = -18; s.players[5].y = -37; }
  const auto out = animate(game);
  EXPECT_NEAR(out[29].players[0].x, game[14].players[0].x, 1e-4);  // holds until the cycle...
  EXPECT_NEAR(out[30].players[0].x, 20.0f, 1e-4);                   // ...then jumps
  EXPECT_NEAR(out[31].players[5].x, -18.0f, 1e-5);
  EXPECT_GT(out[31].players[5].z, 0.9f);
}

}  // namespace
}  // namespace mc::anim
