#include "anim/kick_reach.hpp"

#include <array>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "anim/limb_clearance.hpp"
#include "anim/local_to_model_job.hpp"
#include "proto/pose_frame.hpp"

namespace mc::anim {
namespace {

constexpr float kPelvisH = 0.93f, kBallR = 0.085f, kGap = 0.004f;

std::vector<glm::mat4> posed(const std::array<float, kMaxDof>& a) {
  std::vector<glm::mat4> m(human_skeleton().joints.size());
  LocalToModelJob fk{&human_skeleton(), a, glm::vec3(0, kPelvisH, 0), m};
  EXPECT_TRUE(fk.Run());
  return m;
}

// The right foot's box to the ball's surface (m).
float gap_to(const std::array<float, kMaxDof>& a, const glm::vec3& ball) {
  const std::vector<glm::mat4> m = posed(a);
  const glm::mat4& f = m[kRFoot];
  const glm::vec3 local = glm::transpose(glm::mat3(f)) * (ball - glm::vec3(f[3]));
  return box_distance(human_skeleton().joints[kRFoot].segment, local, nullptr) - kBallR;
}

// A right leg swinging into the ball with its knee still bent (held there
// by the joint speed limit), the ball 6 cm beyond its toe.
struct HeldKick {
  std::array<float, kMaxDof> a{};
  glm::vec3 ball{0.0f};
  HeldKick() {
    a[dof::kRHip] = 25.0f;
    a[dof::kRKnee] = -40.0f;
    const std::vector<glm::mat4> m = posed(a);
    const Segment& seg = human_skeleton().joints[kRFoot].segment;
    const glm::mat4& f = m[kRFoot];
    const glm::vec3 toe(f * glm::vec4(seg.center[0] + 0.5f * seg.size[0], seg.center[1], seg.center[2], 1.0f));
    ball = toe + glm::normalize(glm::vec3(f[0])) * (kBallR + 0.06f);
  }
};

TEST(KickReach, TheHipTakesTheFootTheKneeCouldNotOntoTheBall) {
  HeldKick k;
  ASSERT_NEAR(gap_to(k.a, k.ball), 0.06f, 0.002f);
  const std::array<float, kMaxDof> before = k.a;
  const float left = reach_ball_with_hip(human_skeleton(), before, kPelvisH, k.ball, kBallR, 0, kGap, 57.0f, k.a);
  const float gap = gap_to(k.a, k.ball);
  EXPECT_NEAR(gap, kGap, 0.003f);
  EXPECT_NEAR(left, gap, 0.003f);  // what it reports is what it left, up to its last turn
  // Only the kicking hip turned; the knee and the ankle kept what the limit left them.
  for (int d = 0; d < dof::kCount; ++d)
    if (d < dof::kRHip || d > dof::kRHip + 2) {
      EXPECT_EQ(k.a[static_cast<std::size_t>(d)], before[static_cast<std::size_t>(d)]) << d;
    }
  const JointDef& thigh = human_skeleton().joints[kRThigh];
  for (int d = 0; d < 3; ++d) {
    EXPECT_GE(k.a[static_cast<std::size_t>(dof::kRHip + d)], thigh.limits[static_cast<std::size_t>(d)][0]);
    EXPECT_LE(k.a[static_cast<std::size_t>(dof::kRHip + d)], thigh.limits[static_cast<std::size_t>(d)][1]);
  }
}

TEST(KickReach, TheHipTurnsNoFurtherThanItsCapFromTheLastFrame) {
  HeldKick k;
  const std::array<float, kMaxDof> last = k.a;
  reach_ball_with_hip(human_skeleton(), last, kPelvisH, k.ball, kBallR, 0, kGap, 1.5f, k.a);
  const float turned = rotation_between(human_skeleton().joints[kRThigh].dofs, &last[dof::kRHip], &k.a[dof::kRHip]);
  EXPECT_LE(turned, 1.5f + 1e-3f);
  EXPECT_GT(turned, 1.0f);  // as much of the way as the cap allows
  const float gap = gap_to(k.a, k.ball);
  EXPECT_LT(gap, 0.06f - 0.01f);
  EXPECT_GT(gap, kGap + 0.01f);
}

TEST(KickReach, AFootAlreadyOnTheBallIsLeftAlone) {
  HeldKick k;
  k.ball -= glm::normalize(k.ball - glm::vec3(posed(k.a)[kRFoot][3])) * 0.058f;  // nearer: about on it
  const std::array<float, kMaxDof> before = k.a;
  ASSERT_LE(gap_to(k.a, k.ball), kGap + 0.001f);
  reach_ball_with_hip(human_skeleton(), before, kPelvisH, k.ball, kBallR, 0, kGap, 57.0f, k.a);
  EXPECT_EQ(k.a, before);
}

TEST(KickReach, AFootHeldInTheBallIsTurnedOutOfIt) {
  HeldKick k;
  k.ball -= glm::normalize(k.ball - glm::vec3(posed(k.a)[kRFoot][3])) * 0.09f;  // 3 cm into it
  const std::array<float, kMaxDof> before = k.a;
  ASSERT_LT(gap_to(k.a, k.ball), -0.025f);
  reach_ball_with_hip(human_skeleton(), before, kPelvisH, k.ball, kBallR, 0, kGap, 57.0f, k.a);
  EXPECT_NEAR(gap_to(k.a, k.ball), kGap, 0.003f);
  for (int d = 0; d < dof::kCount; ++d)
    if (d < dof::kRHip || d > dof::kRHip + 2) {
      EXPECT_EQ(k.a[static_cast<std::size_t>(d)], before[static_cast<std::size_t>(d)]) << d;
    }
}

TEST(KickReach, AFootWithinTheQuantizationOfTheBallIsLeftAlone) {
  HeldKick k;
  k.ball -= glm::normalize(k.ball - glm::vec3(posed(k.a)[kRFoot][3])) * 0.065f;  // 5 mm into it
  const std::array<float, kMaxDof> before = k.a;
  ASSERT_LT(gap_to(k.a, k.ball), 0.0f);
  ASSERT_GT(gap_to(k.a, k.ball), -kDeepInBallM);
  reach_ball_with_hip(human_skeleton(), before, kPelvisH, k.ball, kBallR, 0, kGap, 57.0f, k.a);
  EXPECT_EQ(k.a, before);
}

}  // namespace
}  // namespace mc::anim
