#include "anim/ankle_travel.hpp"

#include <array>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "anim/leg_pose_job.hpp"
#include "proto/pose_frame.hpp"

namespace mc::anim {
namespace {

// Both legs solved with the right ankle at `right_x` (body forward, m) and
// the left under its hip; the pelvis at 0.93 m, the body at `body`.
struct Legs {
  std::array<float, kMaxDof> a{};
  LegPoseJob job;
  Legs(float right_x, float right_h) {
    job.pelvis_height = 0.93f;
    job.feet[0].ankle_ms[0] = right_x; job.feet[0].ankle_ms[1] = right_h; job.feet[0].ankle_ms[2] = 0.11f;
    job.feet[1].ankle_ms[0] = 0.0f; job.feet[1].ankle_ms[1] = 0.08f; job.feet[1].ankle_ms[2] = -0.11f;
    job.angles = std::span<float>(a.data(), a.size());
    job.Run();
  }
};

AnkleTravel travel_of(const Legs& l, const BodyFrame& body) {
  AnkleTravel t;
  ankle_positions(human_skeleton(), l.a, l.job.pelvis_height, body, t.ankle);
  t.pelvis = glm::vec3(body.x, body.y, l.job.pelvis_height);
  t.valid = true;
  return t;
}

// A foot sent from 0.35 m behind the hip to 0.45 m in front between two
// frames of a body standing still (a swing re-planned far off) moves at most
// kAnklePastPelvisM, on the way to its target, and gets there on the frames
// after. The other foot, which did not move, is left alone.
TEST(AnkleTravel, AnAnkleSentFarInOneFrameGetsThereOverSeveralFrames) {
  const BodyFrame body(10.0f, 5.0f, 30.0f);
  const Legs before(-0.35f, 0.20f);
  AnkleTravel last = travel_of(before, body);
  const bool skip[2] = {false, false}, lift[2] = {false, false};
  glm::vec3 prev = last.ankle[0];
  const glm::vec3 left_before = last.ankle[1];
  int frames = 0;
  for (; frames < 5; ++frames) {
    Legs now(0.45f, 0.20f);
    const int pulled = limit_ankle_travel(human_skeleton(), body, last, skip, lift, nullptr, now.job);
    const AnkleTravel after = travel_of(now, body);
    EXPECT_LE(glm::length(after.ankle[0] - prev), kAnklePastPelvisM + 0.01f) << frames;
    EXPECT_LT(glm::length(after.ankle[1] - left_before), 0.01f) << frames;
    EXPECT_EQ(pulled & 2, 0);
    prev = after.ankle[0];
    last = after;
    if (pulled == 0) break;
  }
  EXPECT_EQ(frames, 1) << "0.8 m at 0.5 m a frame: pulled once, then there";
  // Where it ended: on its target.
  float bx, bz;
  body.to_body(prev.x, prev.y, bx, bz);
  EXPECT_NEAR(bx, 0.45f, 0.01f);
}

// A foot the caller leaves free (a kick's strike) moves as solved; a foot
// pulled with `lift` is raised off the straight way by half what is left.
TEST(AnkleTravel, SkippedFeetMoveFreelyAndLiftedFeetRise) {
  const BodyFrame body(0.0f, 0.0f, 0.0f);
  const Legs before(-0.40f, 0.08f);
  const AnkleTravel last = travel_of(before, body);
  {
    Legs now(0.45f, 0.08f);
    const bool skip[2] = {true, false}, lift[2] = {false, false};
    EXPECT_EQ(limit_ankle_travel(human_skeleton(), body, last, skip, lift, nullptr, now.job), 0);
    const Legs free(0.45f, 0.08f);  // as solved (the leg's reach stops it a little short)
    EXPECT_LT(glm::length(travel_of(now, body).ankle[0] - travel_of(free, body).ankle[0]), 1e-4f);
  }
  float low = 0, high = 0;
  for (bool up : {false, true}) {
    Legs now(0.45f, 0.08f);
    const bool skip[2] = {false, false}, lift[2] = {up, false};
    EXPECT_EQ(limit_ankle_travel(human_skeleton(), body, last, skip, lift, nullptr, now.job), 1);
    (up ? high : low) = travel_of(now, body).ankle[0].z;
  }
  EXPECT_GT(high, low + 0.05f) << "0.35 m still to go: raised by 8 cm";
}

// A pose given as angles (a tackle's): the leg's change is scaled down
// until its ankle keeps within the bound, and the bound holds.
TEST(AnkleTravel, APoseGivenAsAnglesIsHeldBackToo) {
  const BodyFrame body(-20.0f, 3.0f, 90.0f);
  const Legs before(-0.40f, 0.15f);
  const AnkleTravel last = travel_of(before, body);
  std::array<float, kMaxDof> a = before.a;
  a[dof::kRHip] += 100.0f;  // the right thigh swung far forward at once
  a[dof::kRKnee] = -5.0f;
  AnkleTravel unheld;
  ankle_positions(human_skeleton(), a, 0.93f, body, unheld.ankle);
  ASSERT_GT(glm::length(unheld.ankle[0] - last.ankle[0]), kAnklePastPelvisM + 0.1f);
  EXPECT_EQ(limit_ankle_travel(human_skeleton(), body, 0.93f, last, before.a, a), 1);
  AnkleTravel held;
  ankle_positions(human_skeleton(), a, 0.93f, body, held.ankle);
  const float moved = glm::length(held.ankle[0] - last.ankle[0]);
  EXPECT_LE(moved, kAnklePastPelvisM + 0.01f);
  EXPECT_GT(moved, 0.5f * kAnklePastPelvisM) << "held back, not frozen";
  // With slack (legs turned out of each other's way), it may go that much
  // further, and no further.
  std::array<float, kMaxDof> b = before.a;
  b[dof::kRHip] += 100.0f;
  b[dof::kRKnee] = -5.0f;
  EXPECT_EQ(limit_ankle_travel(human_skeleton(), body, 0.93f, last, before.a, b, 0.07f), 1);
  AnkleTravel slack;
  ankle_positions(human_skeleton(), b, 0.93f, body, slack.ankle);
  const float further = glm::length(slack.ankle[0] - last.ankle[0]);
  EXPECT_LE(further, kAnklePastPelvisM + 0.07f + 0.01f);
  EXPECT_GT(further, moved + 0.04f);
}

// A kicking foot held back at the end of its backswing one frame before
// its contact, the contact spot 0.8 m ahead: it would have to cover the
// whole way on the contact frame (a pop). With the contact as its goal it
// comes forward now, to within a frame's travel of the spot, and moves no
// more than a frame's travel (with the goal's slack) from where it was.
TEST(AnkleTravel, AKickingFootKeepsWithinAFramesReachOfItsContact) {
  const BodyFrame body(4.0f, -2.0f, 0.0f);  // standing still, facing +x
  const Legs before(-0.35f, 0.20f);
  const AnkleTravel last = travel_of(before, body);
  const bool skip[2] = {false, false}, lift[2] = {false, false};
  AnkleGoal goal[2];
  goal[0].set = true;
  goal[0].at = glm::vec3(body.x + 0.45f, body.y + 0.11f, 0.17f);
  goal[0].frames = 1;
  {
    Legs stay(-0.35f, 0.20f);  // the plan keeps the foot back: no goal, no change
    EXPECT_EQ(limit_ankle_travel(human_skeleton(), body, last, skip, lift, nullptr, stay.job), 0);
  }
  Legs stay(-0.35f, 0.20f);
  EXPECT_EQ(limit_ankle_travel(human_skeleton(), body, last, skip, lift, goal, stay.job), 1);
  const glm::vec3 now = travel_of(stay, body).ankle[0];
  EXPECT_LE(glm::length(goal[0].at - now), kAnklePastPelvisM + 0.01f) << "one frame's travel from the ball";
  EXPECT_LE(glm::length(now - last.ankle[0]), kAnklePastPelvisM + 0.05f + 0.01f);
  // Two frames out, the same spot is within reach already: left alone.
  goal[0].frames = 2;
  Legs early(-0.35f, 0.20f);
  EXPECT_EQ(limit_ankle_travel(human_skeleton(), body, last, skip, lift, goal, early.job), 0);
}

}  // namespace
}  // namespace mc::anim
