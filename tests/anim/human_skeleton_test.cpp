#include "anim/human_skeleton.hpp"

#include <array>
#include <vector>

#include <gtest/gtest.h>

#include "anim/local_to_model_job.hpp"
#include "proto/pose_frame.hpp"

namespace mc::anim {
namespace {

TEST(HumanSkeleton, HasTheSegmentsTheIssueNames) {
  const SkeletonDef& s = human_skeleton();
  EXPECT_GE(s.joints.size(), 15u);
  for (const char* name : {"pelvis", "torso", "neck", "head", "r_upper_arm", "l_upper_arm", "r_lower_arm",
                           "l_lower_arm", "r_thigh", "l_thigh", "r_shin", "l_shin", "r_foot", "l_foot"})
    EXPECT_GE(s.find(name), 0) << name;
  EXPECT_EQ(s.joints.size(), static_cast<std::size_t>(kHumanJointCount));
  EXPECT_EQ(s.dof_count(), dof::kCount);
  EXPECT_LE(s.dof_count(), kMaxDof);
}

TEST(HumanSkeleton, ParentsComeFirstAndEveryDofHasALimit) {
  const SkeletonDef& s = human_skeleton();
  EXPECT_EQ(s.joints[0].parent, -1);
  for (std::size_t i = 1; i < s.joints.size(); ++i) {
    EXPECT_GE(s.joints[i].parent, 0);
    EXPECT_LT(s.joints[i].parent, static_cast<int>(i));
  }
  for (const JointDef& j : s.joints) {
    ASSERT_EQ(j.limits.size(), j.dofs.size()) << j.name;
    for (const auto& l : j.limits) {
      EXPECT_LT(l[0], l[1]) << j.name;
      EXPECT_LE(l[0], 0.0f) << j.name;  // the rest pose (all zero) is legal
      EXPECT_GE(l[1], 0.0f) << j.name;
    }
  }
}

TEST(HumanSkeleton, DofOffsetsMatchTheDefinition) {
  const SkeletonDef& s = human_skeleton();
  std::vector<int> first;
  int k = 0;
  for (const JointDef& j : s.joints) { first.push_back(k); k += static_cast<int>(j.dofs.size()); }
  EXPECT_EQ(first[kRThigh], dof::kRHip);
  EXPECT_EQ(first[kLShin], dof::kLKnee);
  EXPECT_EQ(first[kRFoot], dof::kRAnkle);
  EXPECT_EQ(first[kLUpperArm], dof::kLShoulder);
  EXPECT_EQ(first[kHead], dof::kHead);
}

TEST(HumanSkeleton, IsAboutOnePointEightMetresTallStandingOnTheSoles) {
  const SkeletonDef& s = human_skeleton();
  std::array<float, kMaxDof> angles{};
  std::vector<glm::mat4> m(s.joints.size());
  LocalToModelJob job{&s, angles, glm::vec3(0, dims::kStandPelvis, 0), m};
  ASSERT_TRUE(job.Run());
  const float ankle = m[kRFoot][3].y;
  EXPECT_NEAR(ankle, dims::kAnkleHeight, 1e-5f);
  const auto& head = s.joints[kHead].segment;
  const float top = m[kHead][3].y + head.center[1] + head.size[0];
  EXPECT_NEAR(top, 1.8f, 0.06f);
  // Right is +Z.
  EXPECT_GT(m[kRThigh][3].z, 0.0f);
  EXPECT_LT(m[kLUpperArm][3].z, 0.0f);
}

}  // namespace
}  // namespace mc::anim
