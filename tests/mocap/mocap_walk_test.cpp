// The mocap mode's slow walk (MocapMotionSource::walk over the CMU motion
// graph, held on the grass by anim/player_animation): the graph walk plants
// both feet in turn; a player walking at 1 m/s is animated from it with
// finite angles inside the joint limits, planted feet that do not slide,
// a human cadence and no joint jump; a source without a walk changes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

const std::string kDir = std::string(MATCHCAST_MOCAP_DIR) + "";

std::shared_ptr<const MocapMotionSource> walk_source() {
  static const auto s = [] {
    std::string error;
    auto p = io::load_mocap_motion_source_with_walk(kDir, MATCHCAST_MOCAP_CACHE, error);
    EXPECT_NE(p, nullptr) << error;
    return p;
  }();
  return s;
}

TEST(MocapWalk, TheGraphWalkPlantsBothFeetInTurn) {
  ASSERT_NE(walk_source(), nullptr);
  ASSERT_TRUE(walk_source()->has_walk());
  WalkCursor c;
  int planted[2] = {0, 0}, lifted[2] = {0, 0};
  for (int f = 0; f < 60; ++f) {  // 3 s at 20 frames/s
    WalkPose p;
    ASSERT_TRUE(walk_source()->walk(c, 1.2f, 0, 0.05f, p));
    ASSERT_GE(c.node, 0);
    for (int i = 0; i < 2; ++i) {
      for (float v : p.feet[i].ankle_ms) ASSERT_TRUE(std::isfinite(v));
      (p.planted[i] ? planted : lifted)[i]++;
    }
    EXPECT_GT(p.pelvis_height, 0.6f);
    EXPECT_LT(p.pelvis_height, 1.1f);
  }
  for (int i = 0; i < 2; ++i) {
    EXPECT_GT(planted[i], 10) << i;
    EXPECT_GT(lifted[i], 5) << i;
  }
  WalkPose p;
  EXPECT_FALSE(walk_source()->walk(c, std::nanf(""), 0, 0.05f, p));
  EXPECT_FALSE(walk_source()->walk(c, 1, 0, 0, p));
  // A kicks-only source has no walk.
  std::string error;
  const auto kicks = io::load_mocap_motion_source(kDir, error);
  ASSERT_NE(kicks, nullptr) << error;
  WalkCursor k;
  EXPECT_FALSE(kicks->walk(k, 1, 0, 0.05f, p));
}

using Animated = testing::AnimatedGame;
constexpr auto animate = testing::animate_game;

TEST(MocapWalk, ASlowWalkIsAnimatedFromTheGraphWithinTheTargets) {
  ASSERT_NE(walk_source(), nullptr);
  const auto game = testing::run_game(80, 0.1, 5);  // left 1 walks at 1 m/s from cycle 5
  AnimConfig cfg;
  cfg.motion_source = walk_source();
  const Animated m = animate(game, cfg);
  const Animated k = animate(game, {});
  ASSERT_EQ(m.frames.size(), 2 * game.size());
  int differing = 0, walking = 0, planted = 0;
  for (std::size_t i = 0; i < m.frames.size(); ++i) {
    for (const PlayerPose& p : m.frames[i].players) {
      std::array<float, dof::kCount> a{};
      std::copy(p.angles.begin(), p.angles.begin() + dof::kCount, a.begin());
      for (float v : a) ASSERT_TRUE(std::isfinite(v));
      EXPECT_EQ(clamp_to_limits(human_skeleton(), a), 0) << "seq " << m.frames[i].seq;
    }
    if (m.infos[i].players[0].action != Action::Walk) continue;
    ++walking;
    differing += m.frames[i].players[0].angles != k.frames[i].players[0].angles;
    planted += m.infos[i].players[0].planted[0] || m.infos[i].players[0].planted[1];
  }
  std::printf("walking frames %d: %d from the graph, %d with a foot held\n", walking, differing, planted);
  ASSERT_GT(walking, 100);
  EXPECT_GT(differing, walking * 3 / 4);  // the walk is the graph's
  EXPECT_GT(planted, walking / 2);        // and stands on its feet
  GameParams params;
  const tools::QualityReport q = tools::measure(human_skeleton(), game, m.frames, m.infos, m.events, params.ball_size());
  EXPECT_LE(q.slide_m.mean(), 0.02) << tools::format_report(q);
  // The leg lags a frame or two behind the capture's fast knee at heel
  // strike (joint speed limit): measured 9.5 cm at worst here.
  EXPECT_LE(q.slide_m.max(), 0.12) << tools::format_report(q);
  EXPECT_LE(q.cadence.max(), 4.5) << tools::format_report(q);
  EXPECT_LE(q.max_jump_deg, tools::kMaxJumpTarget) << tools::format_report(q);
  EXPECT_LE(q.root_error_m.max(), 0.01);
  EXPECT_GE(q.lowest_m, -tools::kGroundTolerance);
}

TEST(MocapWalk, ASourceWithoutAWalkLeavesWalkingAlone) {
  std::string error;
  const auto kicks = io::load_mocap_motion_source(kDir, error);
  ASSERT_NE(kicks, nullptr) << error;
  const auto game = testing::run_game(40, 0.1, 5);
  AnimConfig cfg;
  cfg.motion_source = kicks;
  const Animated m = animate(game, cfg);
  const Animated k = animate(game, {});
  ASSERT_EQ(m.frames.size(), k.frames.size());
  for (std::size_t i = 0; i < m.frames.size(); ++i) {
    const PlayerPose& a = m.frames[i].players[0];
    const PlayerPose& b = k.frames[i].players[0];
    ASSERT_TRUE(a.angles == b.angles && a.x == b.x && a.y == b.y && a.z == b.z) << "frame " << i;
  }
}

}  // namespace
}  // namespace mc::anim::mocap
