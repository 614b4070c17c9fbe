#include "anim/action_motion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "anim/kick_planner.hpp"
#include "anim/local_to_model_job.hpp"
#include "proto/pose_frame.hpp"

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

TEST(SampleAction, TackleAndDiveAreWholeBodyMotions) {
  for (MotionKind kind : {MotionKind::Tackle, MotionKind::Dive}) {
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

// A catch is the upper body's and a lower pelvis: the legs keep their
// footsteps (ground_contact_test.cpp, a catch on the run).
TEST(SampleAction, ACatchLeavesTheLegsToTheirFootsteps) {
  ActionMotion m;
  m.kind = MotionKind::Catch;
  m.start_s = -0.15f;
  m.end_s = 0.5f;
  const ActionSample s = sample_action(m, 0.2f, 0, 0, 0);
  EXPECT_FALSE(s.whole_body);
  EXPECT_FALSE(s.feet);
  EXPECT_GT(s.weight, 0.9f);
  EXPECT_LT(s.pelvis_height, 0.9f);
  EXPECT_GT(s.angles[dof::kRShoulder], 60.0f);
  EXPECT_GT(s.angles[dof::kLShoulder], 60.0f);
}

// The whole-body poses keep every joint above the grass (and the pelvis
// within a body length of it).
TEST(SampleAction, WholeBodyPosesStayAboveTheGrass) {
  const SkeletonDef& skel = human_skeleton();
  for (MotionKind kind : {MotionKind::Tackle, MotionKind::Dive}) {
    for (float side : {1.0f, -1.0f}) {
      ActionMotion m;
      m.kind = kind;
      m.side = side;
      m.foot = side > 0 ? Foot::Right : Foot::Left;
      m.start_s = -0.15f;
      m.end_s = 0.9f;
      const ActionSample s = sample_action(m, 0.4f, 0, 0, 0);
      std::array<float, kMaxDof> a{};
      for (int d = 0; d < dof::kCount; ++d) a[static_cast<std::size_t>(d)] = s.angles[static_cast<std::size_t>(d)];
      std::vector<glm::mat4> models(skel.joints.size());
      LocalToModelJob fk{&skel, a, glm::vec3(0, s.pelvis_height, 0), models};
      ASSERT_TRUE(fk.Run());
      float lowest = 10;
      for (const glm::mat4& j : models) lowest = std::min(lowest, j[3].y);
      EXPECT_GT(lowest, -0.02f) << static_cast<int>(kind) << " side " << side;
      EXPECT_LT(lowest, 0.25f) << static_cast<int>(kind) << " side " << side;  // something touches the grass
    }
  }
}

}  // namespace
}  // namespace mc::anim
