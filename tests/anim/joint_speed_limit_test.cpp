// limit_joint_speed: a joint that turns further than its group's limit
// since the last frame is scaled back along its own turn to within it;
// the others, a kicking leg within the kick's higher limit and a knee
// within its own, are left.
#include "anim/joint_speed_limit.hpp"

#include <gtest/gtest.h>

#include <array>

#include "anim/local_to_model_job.hpp"
#include "anim/player_animation.hpp"

namespace mc::anim {
namespace {

float turn(const std::array<float, dof::kCount>& last, const std::array<float, dof::kCount>& a, int first) {
  const auto& dofs = human_skeleton().joints[static_cast<std::size_t>(kRThigh)].dofs;
  return rotation_between(dofs, last.data() + first, a.data() + first);
}

TEST(JointSpeedLimit, ALegTurningFasterThanTheLimitIsHeldBackAlongItsTurn) {
  std::array<float, dof::kCount> last{}, a{};
  a[dof::kRHip] = 70.0f;      // flexion: 70 deg in one frame
  a[dof::kRHip + 1] = -10.0f;
  a[dof::kLHip] = 20.0f;      // the other leg within its limit
  a[dof::kRShoulder] = 30.0f;  // an arm within its own
  const auto before = a;
  bool limited[kHumanJointCount] = {};
  limit_joint_speed(human_skeleton(), last.data(), a, limited, -1);
  EXPECT_TRUE(limited[kRThigh]);
  EXPECT_LE(turn(last, a, dof::kRHip), kMaxLegStepDeg);
  EXPECT_GT(turn(last, a, dof::kRHip), kMaxLegStepDeg - 1.0f);  // no further back than it needs
  // Along its own turn: the two dofs keep their proportion.
  EXPECT_NEAR(a[dof::kRHip] / a[dof::kRHip + 1], before[dof::kRHip] / before[dof::kRHip + 1], 1e-3f);
  EXPECT_FALSE(limited[kLThigh]);
  EXPECT_EQ(a[dof::kLHip], before[dof::kLHip]);
  EXPECT_EQ(a[dof::kRShoulder], before[dof::kRShoulder]);
}

TEST(JointSpeedLimit, TheKickingLegHasTheKicksLimitAndAnArmItsOwn) {
  std::array<float, dof::kCount> last{}, a{};
  a[dof::kRHip] = 55.0f;  // over the leg's limit, within the kick's
  a[dof::kLShoulder] = kMaxUpperStepDeg + 10.0f;
  bool limited[kHumanJointCount] = {};
  limit_joint_speed(human_skeleton(), last.data(), a, limited, 0);
  EXPECT_FALSE(limited[kRThigh]);
  EXPECT_EQ(a[dof::kRHip], 55.0f);
  EXPECT_TRUE(limited[kLUpperArm]);
  EXPECT_LE(a[dof::kLShoulder], kMaxUpperStepDeg);
  // Not kicking, the same leg is held to the running limit.
  a[dof::kRHip] = 55.0f;
  limit_joint_speed(human_skeleton(), last.data(), a, limited, -1);
  EXPECT_TRUE(limited[kRThigh]);
  EXPECT_LE(a[dof::kRHip], kMaxLegStepDeg);
}

TEST(JointSpeedLimit, AKneeFoldsFasterThanTheRestOfTheLeg) {
  // A swing knee folding 54 deg after toe-off keeps its turn; the hip the
  // same 54 deg is held to the leg's limit, and a knee past its own is held.
  std::array<float, dof::kCount> last{}, a{};
  a[dof::kRKnee] = -54.0f;
  a[dof::kLHip] = 54.0f;
  bool limited[kHumanJointCount] = {};
  limit_joint_speed(human_skeleton(), last.data(), a, limited, -1);
  EXPECT_FALSE(limited[kRShin]);
  EXPECT_EQ(a[dof::kRKnee], -54.0f);
  EXPECT_TRUE(limited[kLThigh]);
  EXPECT_LE(a[dof::kLHip], kMaxLegStepDeg);
  a[dof::kRKnee] = -(kMaxKneeStepDeg + 6.0f);
  limit_joint_speed(human_skeleton(), last.data(), a, limited, -1);
  EXPECT_TRUE(limited[kRShin]);
  EXPECT_GE(a[dof::kRKnee], -kMaxKneeStepDeg);
  EXPECT_LT(a[dof::kRKnee], -(kMaxKneeStepDeg - 1.0f));
}

}  // namespace
}  // namespace mc::anim
