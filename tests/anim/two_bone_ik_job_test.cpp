#include "anim/two_bone_ik_job.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "proto/pose_frame.hpp"

namespace mc::anim {
namespace {

// Solves the right leg for a target relative to the hip (pelvis space, pelvis
// at rest) and returns where FK puts the ankle, relative to the hip.
glm::vec3 solve_and_place(glm::vec3 target, float twist, bool* reached, float soften = 1.0f) {
  const SkeletonDef& s = human_skeleton();
  std::array<float, kMaxDof> a{};
  TwoBoneIKJob ik;
  ik.upper_length = dims::kThigh;
  ik.lower_length = dims::kShin;
  ik.target[0] = target.x; ik.target[1] = target.y; ik.target[2] = target.z;
  ik.twist_deg = twist;
  ik.soften = soften;
  ik.start_zxy = &a[dof::kRHip];
  ik.hinge_z = &a[dof::kRKnee];
  ik.reached = reached;
  EXPECT_TRUE(ik.Run());
  std::vector<glm::mat4> m(s.joints.size());
  LocalToModelJob fk{&s, a, glm::vec3(0), m};
  EXPECT_TRUE(fk.Run());
  for (float v : a) EXPECT_TRUE(std::isfinite(v));
  EXPECT_LE(a[dof::kRKnee], 0.0f);  // the knee never bends backwards
  return glm::vec3(m[kRFoot][3]) - glm::vec3(m[kRThigh][3]);
}

TEST(TwoBoneIKJob, ReachesReachableTargetsExactly) {
  const glm::vec3 targets[] = {{0.1f, -0.8f, 0.0f}, {0.4f, -0.6f, 0.1f}, {-0.3f, -0.7f, -0.15f},
                               {0.5f, -0.3f, 0.2f}, {0.0f, -0.5f, 0.0f}, {0.2f, -0.75f, -0.05f}};
  for (float twist : {0.0f, 20.0f, -30.0f}) {
    for (const glm::vec3& t : targets) {
      bool reached = false;
      const glm::vec3 got = solve_and_place(t, twist, &reached);
      EXPECT_TRUE(reached);
      EXPECT_NEAR(got.x, t.x, 1e-4f);
      EXPECT_NEAR(got.y, t.y, 1e-4f);
      EXPECT_NEAR(got.z, t.z, 1e-4f);
    }
  }
}

TEST(TwoBoneIKJob, ClampsUnreachableTargetsWithoutNaN) {
  bool reached = true;
  const glm::vec3 far(2.0f, -2.0f, 0.3f);
  const glm::vec3 got = solve_and_place(far, 0, &reached, 0.99f);
  EXPECT_FALSE(reached);
  // Stretched towards the target, as far as the soft reach allows.
  EXPECT_NEAR(glm::length(got), 0.99f * (dims::kThigh + dims::kShin), 1e-4f);
  EXPECT_GT(glm::dot(glm::normalize(got), glm::normalize(far)), 0.999f);
}

TEST(TwoBoneIKJob, HandlesDegenerateTargets) {
  bool reached = true;
  solve_and_place(glm::vec3(0), 0, &reached);   // at the hip itself
  EXPECT_FALSE(reached);
  solve_and_place(glm::vec3(0, 0.001f, 0), 0, &reached);  // too close: inside the inner radius
  EXPECT_FALSE(reached);
}

TEST(TwoBoneIKJob, ValidatesItsInputs) {
  float zxy[3], k;
  TwoBoneIKJob ik;
  ik.start_zxy = zxy;
  ik.hinge_z = &k;
  EXPECT_FALSE(ik.Validate());  // no lengths
  ik.upper_length = ik.lower_length = 0.4f;
  EXPECT_TRUE(ik.Validate());
  ik.target[1] = NAN;
  EXPECT_FALSE(ik.Run());
}

}  // namespace
}  // namespace mc::anim
