#include "anim/mocap/mocap_clip.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mc::anim::mocap;

namespace {
// A root and two hips (left at +X), moving along +Z at 1 m/s, 120 Hz.
MocapClip walker(int frames) {
  MocapClip c;
  c.skeleton.names = {"Hips", "LeftUpLeg", "RightUpLeg"};
  c.skeleton.parents = {-1, 0, 0};
  c.skeleton.offsets = {glm::vec3(0), glm::vec3(0.1f, -0.1f, 0), glm::vec3(-0.1f, -0.1f, 0)};
  c.skeleton.end_site = {false, false, false};
  c.frame_time = 1.0 / 120;
  c.frames = frames;
  for (int f = 0; f < frames; ++f) {
    c.root_position.emplace_back(0, 1, f / 120.0f);
    for (int j = 0; j < 3; ++j) c.local.push_back(glm::angleAxis(f * 0.001f, glm::vec3(0, 1, 0)));
  }
  return c;
}
}  // namespace

TEST(MocapClip, ResampleTo30HzKeepsTimeAndInterpolates) {
  const MocapClip c = walker(121);  // 1 s
  const MocapClip r = resample(c, 30);
  EXPECT_EQ(r.frames, 31);
  EXPECT_NEAR(r.frame_time, 1.0 / 30, 1e-12);
  EXPECT_NEAR(r.root_position[30].z, 1.0f, 1e-5);
  EXPECT_NEAR(r.root_position[15].z, 0.5f, 1e-5);
  // 120 -> 48 Hz falls between source frames: lerp and slerp.
  const MocapClip h = resample(c, 48);
  EXPECT_NEAR(h.root_position[1].z, 1.0f / 48, 1e-5);
  EXPECT_NEAR(glm::angle(h.pose(1)[0]), 2.5f * 0.001f, 1e-4);
}

TEST(MocapClip, DropFramesAndTPoseDetection) {
  MocapClip c = walker(10);
  drop_frames(c, 1);
  EXPECT_EQ(c.frames, 9);
  EXPECT_EQ(c.local.size(), 27u);
  EXPECT_NEAR(c.root_position[0].z, 1 / 120.0f, 1e-6);
  EXPECT_TRUE(looks_like_cgspeed_tpose({0, 0, 0, -21, 0, 8, 11}));
  EXPECT_FALSE(looks_like_cgspeed_tpose({0, 0, 0, -21.2, 0, 8}));
  EXPECT_FALSE(looks_like_cgspeed_tpose({0, 0, 1, -21, 0, 8}));
  EXPECT_FALSE(looks_like_cgspeed_tpose({0, 0, 0, 0, 0, 0}));
}

TEST(MocapClip, FacingIsPerpendicularToTheHips) {
  const MocapClip c = walker(2);
  std::vector<glm::vec3> p;
  forward_kinematics(c, 0, p);
  const glm::vec2 f = facing_xz(p, 1, 2);
  EXPECT_NEAR(f.x, 0, 1e-6);
  EXPECT_NEAR(f.y, 1, 1e-6);  // left hip at +X: facing +Z
}

TEST(MocapClip, RetargetTakesOffsetsByName) {
  MocapClip c = walker(3);
  MocapSkeleton canon = c.skeleton;
  canon.offsets[1] = glm::vec3(0.1f, -0.2f, 0);  // legs twice as long
  canon.offsets[2] = glm::vec3(-0.1f, -0.2f, 0);
  EXPECT_EQ(retarget_offsets(c, canon), 3);
  EXPECT_NEAR(c.skeleton.offsets[1].y, -0.2f, 1e-6);
}
