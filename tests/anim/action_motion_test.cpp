#include "anim/action_motion.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "anim/kick_planner.hpp"

namespace mc::anim {
namespace {

ActionMotion a_kick() {
  KickPlanInput in;
  in.ball_x = 0.5f; in.ball_y = 0.2f; in.after_x = 2.5f; in.after_y = 0.2f;
  return plan_kick(in);
}

TEST(SampleAction, NothingOutsideTheMotion) {
  const ActionMotion m = a_kick();
  EXPECT_EQ(sample_action(m, m.start_s - 0.05f, 0, 0, 0).weight, 0.0f);
  EXPECT_EQ(sample_action(m, m.end_s + 0.05f, 0, 0, 0).weight, 0.0f);
  EXPECT_GT(sample_action(m, 0, 0, 0, 0).weight, 0.99f);
}

TEST(SampleAction, KickingAnkleIsOnTheContactSpotAtContact) {
  const ActionMotion m = a_kick();
  const ActionSample s = sample_action(m, 0, 0, 0, 0);
  const int k = m.foot == Foot::Right ? 0 : 1;
  EXPECT_TRUE(s.feet);
  EXPECT_NEAR(s.foot_x[k], m.contact_x, 1e-5f);
  EXPECT_NEAR(s.foot_y[k], m.contact_y, 1e-5f);
  EXPECT_NEAR(s.foot_h[k], m.contact_h, 1e-5f);
  EXPECT_FALSE(s.planted[k]);
  EXPECT_TRUE(s.planted[1 - k]);  // the support foot is down at contact
  EXPECT_NEAR(s.root_dx, m.lunge_x, 1e-6f);
  // Backswing before contact: behind the contact spot; follow-through: ahead.
  EXPECT_LT(sample_action(m, -0.08f, 0, 0, 0).foot_x[k], m.contact_x - 0.1f);
  EXPECT_GT(sample_action(m, 0.1f, 0, 0, 0).foot_x[k], m.contact_x + 0.1f);
  // No root offset on cycle frames (tau = +-0.05).
  EXPECT_EQ(sample_action(m, 0.05f, 0, 0, 0).root_dx, 0.0f);
  EXPECT_EQ(sample_action(m, -0.05f, 0, 0, 0).root_dx, 0.0f);
}

TEST(SampleAction, TackleCatchAndDiveAreWholeBodyMotions) {
  for (MotionKind kind : {MotionKind::Tackle, MotionKind::Catch, MotionKind::Dive}) {
    ActionMotion m;
    m.kind = kind;
    m.start_s = -0.15f;
    m.end_s = 0.9f;
    const ActionSample s = sample_action(m, 0.3f, 0, 0, 0);
    EXPECT_TRUE(s.whole_body);
    EXPECT_GT(s.weight, 0.9f);
    EXPECT_LT(s.pelvis_height, 0.9f);
    for (float v : s.angles) EXPECT_TRUE(std::isfinite(v));
  }
}

}  // namespace
}  // namespace mc::anim
