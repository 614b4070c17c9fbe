#include "anim/local_to_model_job.hpp"

#include <array>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "proto/pose_frame.hpp"

namespace mc::anim {
namespace {

TEST(LocalToModelJob, FollowsTheSignConventions) {
  const SkeletonDef& s = human_skeleton();
  std::array<float, kMaxDof> angles{};
  std::vector<glm::mat4> m(s.joints.size());
  angles[dof::kRHip] = 90;     // flexion: the foot swings forward
  angles[dof::kLKnee] = -90;   // knee flexion: the shin goes back
  LocalToModelJob job{&s, angles, glm::vec3(0, 1, 0), m};
  ASSERT_TRUE(job.Run());
  EXPECT_NEAR(m[kRShin][3].x, dims::kThigh, 1e-5f);
  EXPECT_NEAR(m[kLFoot][3].x, -dims::kShin, 1e-5f);
  // A positive yaw of the pelvis turns +X towards -Z (left).
  angles = {};
  angles[dof::kPelvis] = 90;
  ASSERT_TRUE(job.Run());
  EXPECT_NEAR(m[kRThigh][3].x, dims::kHipHalfWidth, 1e-5f);  // the right hip comes forward
}

TEST(LocalToModelJob, RejectsShortSpans) {
  const SkeletonDef& s = human_skeleton();
  std::array<float, 4> few{};
  std::vector<glm::mat4> m(s.joints.size());
  EXPECT_FALSE((LocalToModelJob{&s, few, glm::vec3(0), m}.Run()));
  EXPECT_FALSE((LocalToModelJob{nullptr, few, glm::vec3(0), m}.Validate()));
}

TEST(LocalToModelJob, ComposesRotationsInDofOrder) {
  // "zx": R = Rz(a) * Rx(b), intrinsic. Rz(90) * Rx(90) maps +Y to +Z then
  // +Z stays +Z under Rz: so +Y -> +Z.
  const float a[2] = {90, 90};
  const glm::mat3 r = joint_rotation("zx", a);
  const glm::vec3 y = r * glm::vec3(0, 1, 0);
  EXPECT_NEAR(y.z, 1.0f, 1e-5f);
  // +X -> Rz(90): +Y.
  const glm::vec3 x = r * glm::vec3(1, 0, 0);
  EXPECT_NEAR(x.y, 1.0f, 1e-5f);
}

// Run works on four-float columns and leaves out the terms of the product
// known to be zero: every model transform must still be exactly glm's
// parent * local, with the last row 0 0 0 1, over many random poses.
TEST(LocalToModelJob, EachTransformIsExactlyTheParentTimesTheLocal) {
  const SkeletonDef& s = human_skeleton();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> any(-120.0f, 120.0f);
  std::array<float, kMaxDof> angles{};
  std::vector<glm::mat4> m(s.joints.size());
  const glm::vec3 root(0.3f, 0.95f, -0.2f);
  for (int pose = 0; pose < 200; ++pose) {
    for (float& a : angles) a = any(rng);
    ASSERT_TRUE((LocalToModelJob{&s, angles, root, m}.Run()));
    const float* a = angles.data();
    for (std::size_t i = 0; i < s.joints.size(); ++i) {
      const JointDef& j = s.joints[i];
      glm::mat4 local(joint_rotation(j.dofs, a));
      a += j.dofs.size();
      local[3] = glm::vec4(j.offset_ls[0], j.offset_ls[1], j.offset_ls[2], 1.0f);
      if (j.parent < 0) local[3] += glm::vec4(root, 0.0f);
      const glm::mat4 want = j.parent < 0 ? local : m[static_cast<std::size_t>(j.parent)] * local;
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          ASSERT_EQ(m[i][c][r], want[c][r]) << "pose " << pose << " joint " << j.name << " [" << c << "][" << r << "]";
    }
  }
}

// joint_rotation keeps each angle's sine and cosine in a small table:
// thousands of different angles (colliding in it), each asked twice, must
// all give the rotation built independently, never another angle's.
TEST(LocalToModelJob, RememberedAnglesNeverStandInForOthers) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> any(-180.0f, 180.0f);
  for (int i = 0; i < 20000; ++i) {
    const float a[3] = {any(rng), any(rng), i % 7 == 0 ? 0.0f : any(rng)};
    glm::mat4 want(1.0f);
    want = glm::rotate(want, glm::radians(a[0]), glm::vec3(0, 0, 1));
    want = glm::rotate(want, glm::radians(a[1]), glm::vec3(1, 0, 0));
    want = glm::rotate(want, glm::radians(a[2]), glm::vec3(0, 1, 0));
    for (int again = 0; again < 2; ++again) {
      const glm::mat3 r = joint_rotation("zxy", a);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(r[c][k], want[c][k], 2e-6f) << a[0] << " " << a[1] << " " << a[2];
    }
  }
}

// joint_angles undoes joint_rotation for every order of three different
// axes, the middle angle within +-90 (the legs' thighs are "zxy"); any other
// order is refused.
TEST(LocalToModelJob, JointAnglesUndoAJointsRotationInEveryOrder) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> outer(-179.0f, 179.0f), middle(-89.0f, 89.0f);
  for (const char* order : {"xyz", "yzx", "zxy", "xzy", "zyx", "yxz"}) {
    for (int i = 0; i < 2000; ++i) {
      const float a[3] = {outer(rng), middle(rng), outer(rng)};
      float back[3];
      ASSERT_TRUE(joint_angles(order, joint_rotation(order, a), back)) << order;
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(back[k], a[k], 0.05f) << order << " angle " << k;
    }
  }
  float out[3];
  EXPECT_FALSE(joint_angles("zx", glm::mat3(1.0f), out));
  EXPECT_FALSE(joint_angles("zxz", glm::mat3(1.0f), out));
}

}  // namespace
}  // namespace mc::anim
