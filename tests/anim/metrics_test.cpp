#include "anim/tools/metrics.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "synthetic_game.hpp"

namespace mc::anim::tools {
namespace {

struct Animated {
  std::vector<WorldState> states;
  std::vector<PoseFrame> frames;
  std::vector<FrameInfo> infos;
  std::vector<AnimEvent> events;
};

Animated animate(std::vector<WorldState> g) {
  Animated r;
  r.states = std::move(g);
  GameParams params;
  Animator a(human_skeleton(), params);
  a.set_frame_info_sink(&r.infos);
  for (const WorldState& s : r.states) a.push(s, r.frames, &r.events);
  a.finish(r.frames, &r.events);
  return r;
}

TEST(QualityMetrics, HoldOnASyntheticRun) {
  const Animated r = animate(anim::testing::run_game(80, 0.4));
  ASSERT_EQ(r.infos.size(), r.frames.size());
  const QualityReport q = measure(human_skeleton(), r.states, r.frames, r.infos, r.events, 0.085);
  EXPECT_EQ(q.frames, 160);
  EXPECT_LE(q.root_error_m.max(), 1e-4);
  EXPECT_EQ(q.limit_violations, 0);
  EXPECT_LE(q.max_jump_deg, kMaxJumpTarget);
  EXPECT_LE(q.cadence.max(), 4.5);
  EXPECT_LE(q.slide_m.mean(), 0.02);
  EXPECT_GT(q.cadence.values.size(), 5u);
  EXPECT_TRUE(targets_hold(q));
  EXPECT_NE(format_report(q).find("PASS"), std::string::npos);
}

TEST(QualityMetrics, CatchWhatTheyMeasure) {
  Animated r = animate(anim::testing::run_game(40, 0.4));
  r.frames[20].players[0].x += 0.05f;                           // the root off its 2D position
  r.frames[30].players[0].angles[dof::kRKnee] = 10;            // a knee bent backwards
  r.frames[31].players[0].angles[dof::kTorso + 1] += 25.0f;     // a jump of the torso
  const QualityReport q = measure(human_skeleton(), r.states, r.frames, r.infos, r.events, 0.085);
  EXPECT_NEAR(q.root_error_m.max(), 0.05, 1e-4);
  EXPECT_EQ(q.limit_violations, 1);
  EXPECT_GE(q.max_jump_deg, 24.0);
  EXPECT_FALSE(targets_hold(q));
}

}  // namespace
}  // namespace mc::anim::tools
