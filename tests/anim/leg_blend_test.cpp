// LegBlend: a foot on the grass in two frames stays on its spot in the
// drawn frames between them; other legs keep the angle blend.
#include "anim/leg_blend.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "anim/human_skeleton.hpp"
#include "anim/leg_pose_job.hpp"
#include "anim/local_to_model_job.hpp"

namespace mc::anim {
namespace {

// A player at field (x, 0) facing +x whose feet are at the given body-space
// ankles (pelvis 0.93 m up, leaning a little forward).
PlayerPose stance(float x, float right_ankle_x, float left_ankle_x, float left_ankle_h, float right_ankle_h = 0.08f) {
  PlayerPose p;
  p.side = Side::Left;
  p.unum = 7;
  p.x = x;
  p.z = 0.93f;
  p.angles[dof::kPelvis + 1] = -6;
  LegPoseJob job;
  job.pelvis_height = p.z;
  job.feet[0].ankle_ms[0] = right_ankle_x; job.feet[0].ankle_ms[1] = right_ankle_h; job.feet[0].ankle_ms[2] = 0.11f;
  job.feet[1].ankle_ms[0] = left_ankle_x; job.feet[1].ankle_ms[1] = left_ankle_h; job.feet[1].ankle_ms[2] = -0.11f;
  job.angles = std::span<float>(p.angles.data(), p.angles.size());
  EXPECT_TRUE(job.Run());
  return p;
}

// The ankle of one side (0 right, 1 left) in field x and height.
glm::vec3 ankle(const PlayerPose& p, int side) {
  const SkeletonDef& s = human_skeleton();
  std::vector<glm::mat4> m(s.joints.size());
  LocalToModelJob fk{&s, std::span<const float>(p.angles.data(), p.angles.size()), glm::vec3(0, p.z, 0), m};
  EXPECT_TRUE(fk.Run());
  const glm::vec3 a(m[static_cast<std::size_t>(side == 0 ? kRFoot : kLFoot)][3]);
  return {p.x + a.x, a.y, a.z};
}

PlayerPose angle_blend(const PlayerPose& a, const PlayerPose& b, float t) {
  PlayerPose o = a;
  o.x = a.x + (b.x - a.x) * t;
  o.z = a.z + (b.z - a.z) * t;
  for (std::size_t k = 0; k < o.angles.size(); ++k) o.angles[k] = a.angles[k] + (b.angles[k] - a.angles[k]) * t;
  return o;
}

TEST(LegBlend, APlantedFootStaysOnItsSpotBetweenFrames) {
  const LegBlend legs(human_skeleton());
  ASSERT_TRUE(legs.ready());
  // The body moves 0.3 m over the planted right foot (field x 0.15); the
  // left foot swings 0.3 m up in the air.
  const PlayerPose a = stance(0.0f, 0.15f, -0.35f, 0.25f);
  const PlayerPose b = stance(0.3f, -0.15f, 0.05f, 0.22f);
  ASSERT_NEAR(ankle(a, 0).x, ankle(b, 0).x, 1e-3f);
  float blend_error = 0;
  for (float t : {1.0f / 3, 0.5f, 2.0f / 3}) {
    const PlayerPose blended = angle_blend(a, b, t);
    blend_error = std::max(blend_error, glm::length(ankle(blended, 0) - ankle(a, 0)));
    PlayerPose o = blended;
    legs.apply(a, b, t, o);
    EXPECT_LT(glm::length(ankle(o, 0) - ankle(a, 0)), 0.002f) << "t " << t;
    // The swinging leg keeps the angle blend's arc.
    for (int k = dof::kLHip; k < dof::kLAnkle + 2; ++k)
      EXPECT_EQ(o.angles[static_cast<std::size_t>(k)], blended.angles[static_cast<std::size_t>(k)]) << "dof " << k;
  }
  // Without it the planted foot would move (what the test is about).
  EXPECT_GT(blend_error, 0.005f);
}

TEST(LegBlend, WithLiftAndLandALeavingFootStaysUntilItsSoleClearsTheGrass) {
  // The right foot leaves the grass: on it in a, 0.25 m forward and 0.14 m
  // up in b.
  const PlayerPose a = stance(0.0f, 0.15f, -0.35f, 0.25f);
  const PlayerPose b = stance(0.3f, 0.1f, 0.05f, 0.22f, 0.22f);
  const float t = 0.15f;  // early: the sole is still within 3 cm of the grass
  const PlayerPose blended = angle_blend(a, b, t);
  PlayerPose planted_only = blended, lift = blended;
  LegBlend(human_skeleton(), false).apply(a, b, t, planted_only);
  LegBlend(human_skeleton(), true).apply(a, b, t, lift);
  EXPECT_EQ(planted_only.angles, blended.angles);  // not on the grass in both: left alone
  const glm::vec3 start = ankle(a, 0);
  auto across = [&](const PlayerPose& p) { return std::hypot(ankle(p, 0).x - start.x, ankle(p, 0).z - start.z); };
  EXPECT_GT(across(blended), 0.02f);  // the angle blend drags it forward
  EXPECT_LT(across(lift), 0.005f);
}

TEST(LegBlend, TheFramesThemselvesAndTeleportsAreLeftAlone) {
  const LegBlend legs(human_skeleton());
  const PlayerPose a = stance(0.0f, 0.15f, -0.35f, 0.25f);
  PlayerPose b = stance(0.3f, -0.15f, 0.05f, 0.22f);
  PoseFrame fa, fb;
  fa.players[0] = a;
  fb.players[0] = b;
  for (float t : {0.0f, 1.0f}) {
    PoseFrame o = fa;
    o.players[0] = angle_blend(a, b, t);
    const PlayerPose before = o.players[0];
    legs.apply(fa, fb, t, o);
    EXPECT_EQ(o.players[0].angles, before.angles);
  }
  fb.players[0].x += 6.0f;  // a move at kick-off
  PoseFrame o = fa;
  o.players[0] = angle_blend(a, fb.players[0], 0.5f);
  const PlayerPose before = o.players[0];
  legs.apply(fa, fb, 0.5f, o);
  EXPECT_EQ(o.players[0].angles, before.angles);
}

TEST(LegBlend, ASkeletonWithoutLegsIsNotTouched) {
  SkeletonDef s;
  s.joints.push_back(JointDef{"root", -1, {0, 0, 0}, "y", {{-180, 180}}, {}});
  const LegBlend legs(s);
  EXPECT_FALSE(legs.ready());
  PlayerPose a, b, o;
  a.side = b.side = o.side = Side::Left;
  o.angles[0] = 12;
  legs.apply(a, b, 0.5f, o);
  EXPECT_EQ(o.angles[0], 12);
}

}  // namespace
}  // namespace mc::anim
