#include "anim/two_bone_ik_job.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
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

TEST(TwoBoneIKJob, TwoRunInStepGiveWhatEachGivesAlone) {
  // run_both interleaves two jobs stage by stage (LegPoseJob's two legs):
  // each job's answer must be its own Run()'s, to the bit, whatever the
  // other one is: reachable, clamped, degenerate, or invalid.
  std::mt19937 rng(40);
  std::uniform_real_distribution<float> coord(-1.2f, 1.2f), twist(-60.0f, 60.0f), soften(0.9f, 1.0f);
  auto random_job = [&](TwoBoneIKJob& j, int kind) {
    j.upper_length = dims::kThigh;
    j.lower_length = dims::kShin;
    j.target[0] = coord(rng);
    j.target[1] = coord(rng);
    j.target[2] = coord(rng);
    j.twist_deg = twist(rng);
    j.soften = soften(rng);
    j.hinge_sign = kind % 2 == 0 ? -1.0f : 1.0f;
    if (kind == 3) j.target[0] = j.target[1] = j.target[2] = 0;  // degenerate
    if (kind == 5) j.target[2] = NAN;                           // invalid: left as it was
  };
  auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v); };
  int compared = 0;
  for (int n = 0; n < 4000; ++n) {
    std::array<std::array<float, 4>, 2> alone{}, paired{};  // hip (3), knee per job
    for (auto* out : {&alone, &paired})
      for (auto& o : *out) o = {1.5f, -2.5f, 3.5f, -4.5f};  // what an invalid job leaves
    bool reached_alone[2] = {false, false}, reached_paired[2] = {true, true};
    TwoBoneIKJob a[2], b[2];
    for (int j = 0; j < 2; ++j) {
      random_job(a[j], (n + 3 * j) % 6);
      b[j] = a[j];
      a[j].start_zxy = alone[j].data();
      a[j].hinge_z = &alone[j][3];
      a[j].reached = &reached_alone[j];
      b[j].start_zxy = paired[j].data();
      b[j].hinge_z = &paired[j][3];
      b[j].reached = &reached_paired[j];
    }
    const bool ran_alone[2] = {a[0].Run(), a[1].Run()};
    bool ran_paired[2] = {!ran_alone[0], !ran_alone[1]};
    run_both(b[0], b[1], ran_paired);
    for (int j = 0; j < 2; ++j) {
      EXPECT_EQ(ran_paired[j], ran_alone[j]) << n << " " << j;
      if (ran_alone[j]) {
        EXPECT_EQ(reached_paired[j], reached_alone[j]) << n << " " << j;
      }
      for (int k = 0; k < 4; ++k) EXPECT_EQ(bits(paired[j][k]), bits(alone[j][k])) << n << " " << j << " " << k;
      compared += ran_alone[j] ? 1 : 0;
    }
  }
  EXPECT_GT(compared, 6000);
}

}  // namespace
}  // namespace mc::anim
