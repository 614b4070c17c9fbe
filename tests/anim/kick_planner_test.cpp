#include "anim/kick_planner.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "anim/action_motion.hpp"
#include "anim/body_frame.hpp"

namespace mc::anim {
namespace {

KickPlanInput kick_at(float ball_fwd, float ball_right, float dir_deg) {
  // Body at the origin facing +x (field +y is the body's right).
  KickPlanInput in;
  in.heading = 0;
  in.ball_x = ball_fwd;
  in.ball_y = ball_right;
  in.after_x = ball_fwd + 2.0f * std::cos(dir_deg * kDeg);
  in.after_y = ball_right + 2.0f * std::sin(dir_deg * kDeg);
  in.contact_time_s = 1.0;
  return in;
}

TEST(ChooseFoot, TheFootOnTheBallsSideOrTheOneSwingingAcross) {
  EXPECT_EQ(choose_foot(0.4f, 0.0f), Foot::Right);
  EXPECT_EQ(choose_foot(-0.4f, 0.0f), Foot::Left);
  EXPECT_EQ(choose_foot(0.0f, -0.7f), Foot::Right);  // straight ahead, kicked to the left
  EXPECT_EQ(choose_foot(0.0f, 0.7f), Foot::Left);
}

TEST(PlanKick, LegsNeverCross) {
  // Over balls all round the kickable area and every kick direction, the
  // kicking ankle stays on its own side of the support foot (body space).
  for (float fwd = -0.3f; fwd <= 1.05f; fwd += 0.15f) {
    for (float right = -1.0f; right <= 1.0f; right += 0.1f) {
      if (std::hypot(fwd, right) > 1.085f) continue;
      for (float dir = -180; dir < 180; dir += 15) {
        const ActionMotion m = plan_kick(kick_at(fwd, right, dir));
        const BodyFrame body(m.lunge_x, m.lunge_y, 0);  // as the legs see it at contact
        float ax, az, sx, sz;
        body.to_body(m.contact_x, m.contact_y, ax, az);
        body.to_body(m.support_x, m.support_y, sx, sz);
        const float side = m.foot == Foot::Right ? 1.0f : -1.0f;
        EXPECT_GT(side * (az - sz), 0.05f) << fwd << " " << right << " " << dir;
      }
    }
  }
}

TEST(PlanKick, TheFrontOfTheFootMeetsTheBackOfTheBall) {
  const ActionMotion m = plan_kick(kick_at(0.5f, 0.2f, 0));
  // Ankle + the strike point (0.19 m ahead, 0.04 m below, sole pitched 15 deg toes down).
  const float p = -15.0f * kDeg;
  const float fx = 0.19f * std::cos(p) + 0.04f * std::sin(p), fy = 0.19f * std::sin(p) - 0.04f * std::cos(p);
  const float sx = m.contact_x + std::cos(m.foot_yaw * kDeg) * fx;
  const float sy = m.contact_y + std::sin(m.foot_yaw * kDeg) * fx;
  const float sh = m.contact_h + fy;
  EXPECT_NEAR(sx, 0.5f - 0.085f, 1e-4f);  // kicked along +x: the back of the ball
  EXPECT_NEAR(sy, 0.2f, 1e-4f);
  EXPECT_NEAR(sh, 0.085f, 1e-4f);
  EXPECT_EQ(m.foot, Foot::Right);
  EXPECT_LT(m.start_s, 0.0f);
  EXPECT_GT(m.end_s, m.follow_s);
}

TEST(PlanKick, StepsInOnlyWhenTheFootCannotReach) {
  const ActionMotion near = plan_kick(kick_at(0.35f, 0.15f, 0));
  EXPECT_NEAR(std::hypot(near.lunge_x, near.lunge_y), 0.0f, 1e-4f);
  const ActionMotion far = plan_kick(kick_at(1.0f, 0.3f, 0));
  EXPECT_GT(std::hypot(far.lunge_x, far.lunge_y), 0.1f);
  EXPECT_LE(std::hypot(far.lunge_x, far.lunge_y), kMaxStepIn + 1e-4f);
  EXPECT_GT(far.lunge_x, 0.0f);  // towards the ball
  // Beyond what a step-in may add, the rest is left to a deep lunge.
  const ActionMotion farther = plan_kick(kick_at(1.4f, 0.3f, 0));
  EXPECT_NEAR(std::hypot(farther.lunge_x, farther.lunge_y), kMaxStepIn, 1e-4f);
  EXPECT_LT(farther.pelvis_height, far.pelvis_height);
}

// A ball in front is wound up for in full; one behind the hips is reached
// back for, and the foot's highest point before the contact is lower
// (issue 23: a full wind-up for a ball 0.6 m behind left the knee too bent
// to straighten onto it within the joint speed limit).
TEST(PlanKick, ABallBehindTheHipsIsReachedBackForWithLessWindUp) {
  const ActionMotion front = plan_kick(kick_at(0.5f, 0.2f, 0));
  const ActionMotion behind = plan_kick(kick_at(-0.45f, 0.3f, 0));
  EXPECT_FLOAT_EQ(front.backswing, 1.0f);
  EXPECT_LT(behind.backswing, 0.5f);
  EXPECT_GE(behind.backswing, 0.25f);
  auto highest = [](const ActionMotion& m) {
    float h = 0;
    for (float tau = m.start_s; tau < 0; tau += 0.01f) {
      const ActionSample s = sample_action(m, tau, 0, 0, 0);
      const int k = m.foot == Foot::Right ? 0 : 1;
      h = std::max(h, s.foot_h[k] - m.contact_h);
    }
    return h;
  };
  EXPECT_GT(highest(front), 0.15f);
  EXPECT_LT(highest(behind), 0.11f);
}

TEST(MergeKick, KicksInConsecutiveCyclesBecomeOneLongerKick) {
  ActionMotion m = plan_kick(kick_at(0.5f, 0.2f, 0));
  const float follow = m.follow_s, end = m.end_s;
  EXPECT_TRUE(merge_kick(m, 1.1, 11));       // the next cycle
  EXPECT_NEAR(m.follow_s, follow + 0.1f, 1e-5f);
  EXPECT_NEAR(m.end_s, end + 0.1f, 1e-5f);
  EXPECT_TRUE(merge_kick(m, 1.2, 12));       // and the one after it, counted from the last
  EXPECT_NEAR(m.end_s, end + 0.2f, 1e-5f);
  EXPECT_EQ(m.last_kick_pos, 12u);
  EXPECT_FALSE(merge_kick(m, 1.6, 16));      // 0.4 s later: a new kick
  EXPECT_FALSE(merge_kick(m, 1.2, 12));      // the same kick twice
  ActionMotion t;
  t.kind = MotionKind::Tackle;
  EXPECT_FALSE(merge_kick(t, 0.1, 1));
}

TEST(IsSuccessfulKick, BitsAndCounters) {
  PlayerState prev, cur;
  cur.state = state_bits::kStand | state_bits::kKick;
  EXPECT_TRUE(is_successful_kick(nullptr, cur));
  cur.state |= state_bits::kKickFault;
  EXPECT_FALSE(is_successful_kick(&prev, cur));
  cur.state = state_bits::kStand | state_bits::kKick;
  prev.counters.count = cur.counters.count = 11;
  prev.counters.kick = cur.counters.kick = 3;
  EXPECT_FALSE(is_successful_kick(&prev, cur));  // a pending long kick keeps the bit
  cur.counters.kick = 4;
  EXPECT_TRUE(is_successful_kick(&prev, cur));
}

}  // namespace
}  // namespace mc::anim
