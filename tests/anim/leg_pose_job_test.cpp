#include "anim/leg_pose_job.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "proto/pose_frame.hpp"

namespace mc::anim {
namespace {

TEST(LegPoseJob, PutsBothAnklesOnTheirTargetsWithTheSolesLevel) {
  const SkeletonDef& s = human_skeleton();
  for (float pelvis_yaw : {0.0f, 8.0f, -8.0f}) {
    std::array<float, kMaxDof> a{};
    a[dof::kPelvis] = pelvis_yaw;
    a[dof::kPelvis + 1] = -5;  // leaning forward a little
    LegPoseJob job;
    job.pelvis_height = 0.93f;
    job.feet[0].ankle_ms[0] = 0.25f; job.feet[0].ankle_ms[1] = 0.08f; job.feet[0].ankle_ms[2] = 0.12f;
    job.feet[1].ankle_ms[0] = -0.1f; job.feet[1].ankle_ms[1] = 0.12f; job.feet[1].ankle_ms[2] = -0.1f;
    job.feet[1].yaw_deg = 10;
    job.angles = std::span<float>(a.data(), a.size());
    ASSERT_TRUE(job.Run());
    EXPECT_TRUE(job.reached[0]);
    EXPECT_TRUE(job.reached[1]);
    std::vector<glm::mat4> m(s.joints.size());
    LocalToModelJob fk{&s, a, glm::vec3(0, 0.93f, 0), m};
    ASSERT_TRUE(fk.Run());
    for (int side = 0; side < 2; ++side) {
      const glm::mat4& foot = m[side == 0 ? kRFoot : kLFoot];
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(foot[3][c], job.feet[side].ankle_ms[c], 1e-3f) << side << " " << c;
      // The sole's forward axis is level (pitch 0 asked), within 3 deg: the
      // ankle has no twist dof, so a sole turned against the knee keeps a residue.
      const glm::vec3 fwd = glm::normalize(glm::vec3(foot[0]));
      EXPECT_NEAR(fwd.y, 0.0f, 0.05f) << side;
    }
  }
}

// knee_out_deg turns each knee outward (right towards +Z, left towards -Z)
// over the same ankle: planted legs whose thighs came too close (issue 23).
TEST(LegPoseJob, KneesTurnOutOverTheSameAnkles) {
  const SkeletonDef& s = human_skeleton();
  auto solve = [&](float out, std::vector<glm::mat4>& m) {
    std::array<float, kMaxDof> a{};
    LegPoseJob job;
    job.pelvis_height = 0.88f;  // knees bent: the knee's direction shows
    job.feet[0].ankle_ms[0] = 0.05f; job.feet[0].ankle_ms[1] = 0.08f; job.feet[0].ankle_ms[2] = 0.06f;
    job.feet[1].ankle_ms[0] = 0.05f; job.feet[1].ankle_ms[1] = 0.08f; job.feet[1].ankle_ms[2] = -0.06f;
    job.feet[0].knee_out_deg = job.feet[1].knee_out_deg = out;
    job.angles = std::span<float>(a.data(), a.size());
    ASSERT_TRUE(job.Run());
    m.assign(s.joints.size(), glm::mat4(1.0f));
    LocalToModelJob fk{&s, a, glm::vec3(0, 0.88f, 0), m};
    ASSERT_TRUE(fk.Run());
  };
  std::vector<glm::mat4> straight, out;
  solve(0, straight);
  solve(20, out);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(out[kRFoot][3][c], straight[kRFoot][3][c], 1e-3f) << c;
    EXPECT_NEAR(out[kLFoot][3][c], straight[kLFoot][3][c], 1e-3f) << c;
  }
  // Knees: the shins' origins.
  EXPECT_GT(out[kRShin][3].z, straight[kRShin][3].z + 0.02f);
  EXPECT_LT(out[kLShin][3].z, straight[kLShin][3].z - 0.02f);
}

TEST(LegPoseJob, ClampsUnreachableFeetWithoutNaN) {
  std::array<float, kMaxDof> a{};
  LegPoseJob job;
  job.pelvis_height = 0.95f;
  job.feet[0].ankle_ms[0] = 2.0f;   // far out of reach
  job.feet[0].ankle_ms[1] = 0.08f;
  job.feet[1].ankle_ms[1] = 0.08f;
  job.feet[1].ankle_ms[2] = -0.1f;
  job.angles = std::span<float>(a.data(), a.size());
  ASSERT_TRUE(job.Run());
  EXPECT_FALSE(job.reached[0]);
  EXPECT_TRUE(job.reached[1]);
  for (float v : a) EXPECT_TRUE(std::isfinite(v));
  std::array<float, 4> few{};
  job.angles = std::span<float>(few.data(), few.size());
  EXPECT_FALSE(job.Run());
}

}  // namespace
}  // namespace mc::anim
