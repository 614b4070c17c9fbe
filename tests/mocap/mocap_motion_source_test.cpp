// The animator's mocap mode (anim/mocap/mocap_motion_source, issue 9) on the
// real CMU kicks: the captured kick is bent so the kicking ankle is on the
// plan's contact point at contact, for either foot; in a whole animation the
// angles stay finite and inside the joint limits, the foot meets the ball
// within 5 cm, and only the kicks differ from the keyframe mode.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../anim/synthetic_game.hpp"
#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/joint_limits.hpp"
#include "anim/mocap/io/motion_source_files.hpp"
#include "anim/player_animation.hpp"
#include "anim/tools/metrics.hpp"

namespace mc::anim::mocap {
namespace {

std::shared_ptr<const MocapMotionSource> source() {
  static const auto s = [] {
    std::string error;
    auto p = io::load_mocap_motion_source(std::string(MATCHCAST_MOCAP_DIR) + "", error);
    EXPECT_NE(p, nullptr) << error;
    return p;
  }();
  return s;
}

ActionMotion kick_motion(Foot foot) {
  ActionMotion m;
  m.kind = MotionKind::Kick;
  m.foot = foot;
  m.contact_x = 10.35f;
  m.contact_y = 5.2f;
  m.contact_h = 0.11f;
  m.support_x = 10.1f;
  m.support_y = foot == Foot::Right ? 4.95f : 5.3f;
  m.contact_time_s = 12.3;
  return m;
}

TEST(MocapMotionSource, LoadsTheFiveKicksAndRejectsAMissingFolder) {
  ASSERT_NE(source(), nullptr);
  EXPECT_EQ(source()->kick_count(), 5u);
  std::string error;
  EXPECT_EQ(io::load_mocap_motion_source("/nonexistent-mocap-dir", error), nullptr);
  EXPECT_FALSE(error.empty());
}

TEST(MocapMotionSource, KickingAnkleIsOnTheContactPointAtContactForEitherFoot) {
  ASSERT_NE(source(), nullptr);
  for (Foot foot : {Foot::Right, Foot::Left}) {
    const ActionMotion m = kick_motion(foot);
    const int side = foot == Foot::Right ? 0 : 1;
    ActionSample s = sample_action(m, 0, 20, 10, 5);
    ASSERT_TRUE(source()->kick(m, 0, 20, 10, 5, s));
    EXPECT_NEAR(s.foot_x[side], m.contact_x, 1e-3f);
    EXPECT_NEAR(s.foot_y[side], m.contact_y, 1e-3f);
    EXPECT_NEAR(s.foot_h[side], m.contact_h, 1e-3f);
    // Away from contact the foot follows the capture: elsewhere, finite, above the grass.
    for (float tau : {-0.15f, -0.05f, 0.1f, 0.3f}) {
      ActionSample t = sample_action(m, tau, 20, 10, 5);
      ASSERT_TRUE(source()->kick(m, tau, 20, 10, 5, t));
      EXPECT_TRUE(std::isfinite(t.foot_x[side]) && std::isfinite(t.foot_y[side]) && std::isfinite(t.pelvis_height));
      EXPECT_GE(t.foot_h[side], 0.0f);
      EXPECT_GT(std::hypot(t.foot_x[side] - m.contact_x, t.foot_y[side] - m.contact_y), 0.02f) << tau;
    }
  }
}

TEST(MocapMotionSource, LeavesOtherActionsAlone) {
  ASSERT_NE(source(), nullptr);
  ActionMotion m = kick_motion(Foot::Right);
  m.kind = MotionKind::Tackle;
  ActionSample s = sample_action(m, 0, 0, 10, 5);
  const ActionSample before = s;
  EXPECT_FALSE(source()->kick(m, 0, 0, 10, 5, s));
  m.kind = MotionKind::Kick;  // and a kick at a non-finite time
  EXPECT_FALSE(source()->kick(m, std::nanf(""), 0, 10, 5, s));
  EXPECT_EQ(s.foot_x[0], before.foot_x[0]);
  EXPECT_EQ(s.angles, before.angles);
}

// Left 1 runs up to the ball (0.6 m ahead) and kicks it at cycle k.
std::vector<WorldState> kick_game(int k) {
  auto g = testing::run_game(40, 0.2, 0);
  double ball_x = g[0].players[0].x + 0.6;
  for (std::size_t i = 0; i < g.size(); ++i) {
    ball_x = static_cast<int>(i) >= k ? ball_x + 2.0 : g[i].players[0].x + 0.6;
    g[i].ball.x = ball_x;
    g[i].ball.y = 0.15;
  }
  g[static_cast<std::size_t>(k)].players[0].state |= state_bits::kKick;
  return g;
}

using Animated = testing::AnimatedGame;
constexpr auto animate = testing::animate_game;

TEST(MocapMode, KickMeetsTheBallWithFiniteAnglesInsideTheLimits) {
  ASSERT_NE(source(), nullptr);
  AnimConfig cfg;
  cfg.motion_source = source();
  for (int k : {14, 20, 27}) {  // different contact times: different clips
    const auto game = kick_game(k);
    const Animated r = animate(game, cfg);
    ASSERT_EQ(r.frames.size(), 2 * game.size());
    for (const PoseFrame& f : r.frames)
      for (const PlayerPose& p : f.players) {
        for (float v : p.angles) ASSERT_TRUE(std::isfinite(v));
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        std::array<float, dof::kCount> a{};
        std::copy(p.angles.begin(), p.angles.begin() + dof::kCount, a.begin());
        EXPECT_EQ(clamp_to_limits(human_skeleton(), a), 0) << "seq " << f.seq;
      }
    GameParams params;
    const tools::QualityReport q =
        tools::measure(human_skeleton(), game, r.frames, r.infos, r.events, params.ball_size());
    ASSERT_EQ(q.kicks, 1) << k;
    EXPECT_LE(q.contact_m.max(), 0.05) << "kick at cycle " << k << " plays clip "
                                       << source()->clip_for(ActionMotion{.contact_time_s = (k - 0.5) * 0.1});
    EXPECT_LE(q.root_error_m.max(), 0.01);
    EXPECT_GE(q.lowest_m, -tools::kGroundTolerance);
  }
}

TEST(MocapMode, OnlyTheKickDiffersFromTheKeyframeMode) {
  ASSERT_NE(source(), nullptr);
  const int k = 20;
  const auto game = kick_game(k);
  AnimConfig mocap_cfg;
  mocap_cfg.motion_source = source();
  const Animated key = animate(game, {});
  const Animated moc = animate(game, mocap_cfg);
  ASSERT_EQ(key.frames.size(), moc.frames.size());
  int kick_frames_differing = 0;
  for (std::size_t i = 0; i < key.frames.size(); ++i) {
    for (std::size_t p = 0; p < kMaxPlayers; ++p) {
      const PlayerPose& a = key.frames[i].players[p];
      const PlayerPose& b = moc.frames[i].players[p];
      const bool same = a.angles == b.angles && a.x == b.x && a.y == b.y && a.z == b.z && a.heading == b.heading;
      if (!key.infos[i].players[p].in_action && i < static_cast<std::size_t>(2 * (k - 4))) {
        EXPECT_TRUE(same) << "frame " << i << " player " << p;  // before the kick: byte-equal
      }
      if (key.infos[i].players[p].in_action && !same) ++kick_frames_differing;
    }
  }
  EXPECT_GE(kick_frames_differing, 5);
}

}  // namespace
}  // namespace mc::anim::mocap
