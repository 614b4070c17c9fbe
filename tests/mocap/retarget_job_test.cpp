#include "anim/mocap/retarget_job.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/mocap/io/clip_files.hpp"

using namespace mc::anim::mocap;
namespace anim = mc::anim;

namespace {

MocapClip load(const char* name) {
  MocapClip c;
  std::string error;
  EXPECT_TRUE(io::load_bvh(std::string(MATCHCAST_MOCAP_DIR) + "/" + name, c, error)) << error;
  return resample(c, 30);
}

// Ankle joints of the human pose (body space).
std::array<glm::vec3, 2> ankles(std::span<const float> angles, float pelvis_height) {
  std::vector<glm::mat4> m(anim::human_skeleton().joints.size());
  anim::LocalToModelJob fk;
  fk.skeleton = &anim::human_skeleton();
  fk.angles_deg = angles;
  fk.root_ms = glm::vec3(0, pelvis_height, 0);
  fk.models = m;
  EXPECT_TRUE(fk.Run());
  return {glm::vec3(m[anim::kRFoot][3]), glm::vec3(m[anim::kLFoot][3])};
}

}  // namespace

TEST(MocapRetarget, WalkFeetFollowTheScaledMocapFeet) {
  const MocapClip walk = load("cmu_10_04.bvh");
  ASSERT_GT(walk.frames, 100);
  EXPECT_NEAR(leg_scale(walk), 1.0f, 0.1f);  // subject 10's legs are close to the broadcast skeleton's
  std::vector<float> angles(anim::dof::kCount);
  float pelvis = 0;
  int checked = 0;
  std::vector<glm::vec3> p;
  for (int f = 10; f < walk.frames - 10; f += 7) {
    MocapRetargetJob job;
    job.clip = &walk;
    job.frame = static_cast<float>(f);
    job.angles = angles;
    job.pelvis_height = &pelvis;
    ASSERT_TRUE(job.Run());
    EXPECT_GT(pelvis, 0.85f);
    EXPECT_LT(pelvis, 1.1f);
    // The right ankle's height follows the mocap (the pelvis comes down where
    // the shorter leg would not reach).
    forward_kinematics(walk, f, p);
    const float k = leg_scale(walk);
    const auto a = ankles(angles, pelvis);
    const glm::vec3 rf = p[static_cast<std::size_t>(walk.skeleton.find("RightFoot"))];
    EXPECT_TRUE(job.reached) << f;
    EXPECT_NEAR(a[0].y, rf.y * k, 0.01f) << f;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(MocapRetarget, KickMeetsTheBallAtContactAndFadesOut) {
  const MocapClip kick = load("cmu_10_05.bvh");
  const int contact = kick_contact_frame(kick, true);
  EXPECT_NEAR(contact / 30.0, 2.52, 0.1);  // the data README: peak toe speed at t = 2.52 s
  std::vector<float> angles(anim::dof::kCount), plain(anim::dof::kCount);
  float pelvis = 0, pelvis_plain = 0;
  MocapRetargetJob job;
  job.clip = &kick;
  job.kick_foot = 0;
  job.contact_frame = static_cast<float>(contact);
  job.ankle_target[0] = 0.45f;  // the ball 45 cm ahead, ankle 12 cm up, 10 cm right
  job.ankle_target[1] = 0.12f;
  job.ankle_target[2] = 0.10f;
  job.angles = angles;
  job.pelvis_height = &pelvis;
  job.frame = static_cast<float>(contact);
  ASSERT_TRUE(job.Run());
  ASSERT_TRUE(job.reached);
  const auto a = ankles(angles, pelvis);
  EXPECT_NEAR(a[0].x, 0.45f, 0.01f);
  EXPECT_NEAR(a[0].y, 0.12f, 0.01f);
  EXPECT_NEAR(a[0].z, 0.10f, 0.01f);
  // Past the fade the kick is the plain retarget.
  MocapRetargetJob ref = job;
  ref.kick_foot = -1;
  ref.angles = plain;
  ref.pelvis_height = &pelvis_plain;
  for (float off : {-12.0f, 12.0f}) {
    job.frame = ref.frame = static_cast<float>(contact) + off;
    ASSERT_TRUE(job.Run());
    ASSERT_TRUE(ref.Run());
    for (int d = 0; d < anim::dof::kCount; ++d) EXPECT_NEAR(angles[static_cast<std::size_t>(d)], plain[static_cast<std::size_t>(d)], 1e-3) << d;
  }
}

TEST(MocapRetarget, RefusesWhatItCannotUse) {
  MocapClip bare;
  bare.skeleton.names = {"hip"};
  bare.skeleton.parents = {-1};
  bare.skeleton.offsets = {glm::vec3(0)};
  bare.skeleton.end_site = {false};
  bare.frames = 1;
  bare.root_position = {glm::vec3(0)};
  bare.local = {glm::quat(1, 0, 0, 0)};
  std::vector<float> angles(anim::dof::kCount);
  float pelvis = 0;
  MocapRetargetJob job;
  job.clip = &bare;
  job.angles = angles;
  job.pelvis_height = &pelvis;
  EXPECT_FALSE(job.Run());  // no cgspeed joint names
  const MocapClip walk = load("cmu_10_04.bvh");
  job.clip = &walk;
  EXPECT_TRUE(job.Validate());
  job.frame = static_cast<float>(walk.frames);  // past the end
  EXPECT_FALSE(job.Validate());
  job.frame = 0;
  std::vector<float> short_angles(5);
  job.angles = short_angles;
  EXPECT_FALSE(job.Validate());
}
