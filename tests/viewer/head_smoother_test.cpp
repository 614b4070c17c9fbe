#include "viewer/head_smoother.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "anim/human_skeleton.hpp"

namespace mc::viewer {
namespace {

// anim's skeleton: pelvis, torso, neck, head each "yzx": the neck's yaw is
// angle 6, the head's 9; the right upper arm's first angle is 12.
constexpr int kNeckYaw = 6, kHeadYaw = 9, kArm = 12;

TEST(HeadSmoother, LimitTurnKeepsTheSummedSpeedUnder600DegreesPerSecond) {
  float cur[2] = {0, 0};
  const float target[2] = {60, 60};
  const std::vector<std::vector<int>> groups = {{0, 1}};
  const double dt = 1.0 / 60;
  float prev = 0;
  int frames = 0;
  while (std::fabs(cur[0] + cur[1] - 120) > 0.5f && frames < 100) {
    limit_turn(cur, target, groups, dt);
    EXPECT_LE(cur[0] + cur[1] - prev, kMaxHeadDegPerS * dt + 1e-3);
    EXPECT_NEAR(cur[0], cur[1], 1e-4) << "neck and head together";
    prev = cur[0] + cur[1];
    ++frames;
  }
  EXPECT_GE(frames, 12) << "120 degrees at 600 deg/s take 0.2 s";
  EXPECT_LT(frames, 30);
  EXPECT_EQ(limit_turn(cur, target, groups, 0.0), 0.0f) << "no time, no move";
}

TEST(HeadSmoother, TheDrawnHeadFollowsAtHumanSpeedAndTheRestIsExact) {
  HeadSmoother h(anim::human_skeleton());
  PoseFrame f;
  auto& p = f.players[3];
  p.state = 1;
  p.unum = 4;
  h.apply(f, 0.0);
  p.angles[kNeckYaw] = 60;  // the agent snaps its neck by 120 degrees
  p.angles[kHeadYaw] = 60;
  p.angles[kArm] = 25;
  PoseFrame drawn = f;
  h.apply(drawn, 1.0 / 60);
  EXPECT_LE(drawn.players[3].angles[kNeckYaw] + drawn.players[3].angles[kHeadYaw], 10.0f + 1e-3f);
  EXPECT_EQ(drawn.players[3].angles[kArm], 25) << "the arm as the stream says";
  int t = 0;
  do {
    drawn = f;
    h.apply(drawn, 1.0 / 60);
  } while (drawn.players[3].angles[kNeckYaw] < 59.5f && ++t < 60);
  EXPECT_LT(t, 30) << "there within half a second";
  EXPECT_NEAR(drawn.players[3].angles[kHeadYaw], 60, 0.5) << "where the agent looks";
  // A teleport snaps.
  f.players[3].x = 20;
  f.players[3].angles[kNeckYaw] = -60;
  drawn = f;
  h.apply(drawn, 1.0 / 60);
  EXPECT_EQ(drawn.players[3].angles[kNeckYaw], -60);
}

}  // namespace
}  // namespace mc::viewer
