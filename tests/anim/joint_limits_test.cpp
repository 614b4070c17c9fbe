#include "anim/joint_limits.hpp"

#include <array>
#include <random>

#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "proto/pose_frame.hpp"

namespace mc::anim {
namespace {

// The built-in skeleton is clamped from a table made once; a copy of it (at
// another address) by walking its joints. Both must clamp alike.
TEST(JointLimits, TheBuiltInSkeletonsTableClampsAsItsJointsDo) {
  const SkeletonDef copy = human_skeleton();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-200.0f, 200.0f);
  int out_total = 0;
  for (int n = 0; n < 200; ++n) {
    std::array<float, kMaxDof> a{};
    for (int d = 0; d < dof::kCount; ++d) a[static_cast<std::size_t>(d)] = u(rng);
    std::array<float, kMaxDof> b = a;
    const int out_a = clamp_to_limits(human_skeleton(), a);
    const int out_b = clamp_to_limits(copy, b);
    EXPECT_EQ(out_a, out_b);
    EXPECT_EQ(a, b);
    out_total += out_a;
  }
  EXPECT_GT(out_total, 200);  // the angles were out, and were counted
}

TEST(JointLimits, EveryClampedAngleIsWithinItsDofsLimits) {
  std::array<float, kMaxDof> a{};
  a.fill(500.0f);
  EXPECT_EQ(clamp_to_limits(human_skeleton(), a), dof::kCount);
  std::size_t k = 0;
  for (const JointDef& j : human_skeleton().joints)
    for (std::size_t d = 0; d < j.dofs.size(); ++d, ++k) EXPECT_EQ(a[k], j.limits[d][1]) << "dof " << k;
  EXPECT_EQ(clamp_to_limits(human_skeleton(), a), 0);
  // The legs' clamp leaves the upper body alone.
  a.fill(-500.0f);
  clamp_legs_to_limits(human_skeleton(), a);
  EXPECT_EQ(a[static_cast<std::size_t>(dof::kPelvis)], -500.0f);
  EXPECT_EQ(a[static_cast<std::size_t>(dof::kRKnee)], human_skeleton().joints[kRShin].limits[0][0]);
}

}  // namespace
}  // namespace mc::anim
