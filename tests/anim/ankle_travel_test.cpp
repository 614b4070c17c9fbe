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

// The clients' drawing of a frame (proto/SPEC.md 4.7 step 1): the root and
// every angle blended linearly. The fastest third of leg `i`'s ankle, over
// the grass and about the pelvis, in m per frame.
struct Drawn {
  float world = 0, rel = 0;
};
Drawn fastest_third(const std::array<float, dof::kCount>& from, const DrawnRoot& last,
                    const std::array<float, dof::kCount>& to, const DrawnRoot& now, int i) {
  glm::vec3 ankle[4][2], pelvis[4];
  for (int n = 0; n < 4; ++n) {
    const float t = static_cast<float>(n) / 3.0f;
    std::array<float, dof::kCount> q{};
    for (std::size_t k = 0; k < q.size(); ++k) q[k] = from[k] + (to[k] - from[k]) * t;
    const DrawnRoot r{last.x + (now.x - last.x) * t, last.y + (now.y - last.y) * t,
                      last.height + (now.height - last.height) * t, last.heading + (now.heading - last.heading) * t};
    ankle_positions(human_skeleton(), q, r.height, BodyFrame(r.x, r.y, r.heading), ankle[n]);
    pelvis[n] = glm::vec3(r.x, r.y, r.height);
  }
  Drawn d;
  for (int n = 0; n < 3; ++n) {
    const glm::vec3 move = ankle[n + 1][i] - ankle[n][i];
    d.world = std::max(d.world, 3.0f * glm::length(move));
    d.rel = std::max(d.rel, 3.0f * glm::length(move - (pelvis[n + 1] - pelvis[n])));
  }
  return d;
}

// A right leg swinging forward from behind the hip while its knee folds
// (hip -10 -> 30 deg, knee -10 -> -120): its ankle ends 0.45 m from where
// it was, within a frame's chord, but blended linearly it moves along a
// curve, and its middle third goes at 0.65 m a frame about the pelvis,
// past the 0.6 (a pop at 60 Hz). The leg is held back until every
// third keeps within kDrawnPopRelM, by no more than it must; the left leg,
// which does not move, is left alone.
struct Swing {
  std::array<float, dof::kCount> from{}, to{};
  DrawnRoot last{10.0f, 5.0f, 0.93f, 30.0f}, now{10.0f, 5.0f, 0.93f, 30.0f};
  Swing() {
    from[dof::kRHip] = -10.0f; from[dof::kRKnee] = -10.0f;
    to[dof::kRHip] = 30.0f; to[dof::kRKnee] = -120.0f;
    from[dof::kLKnee] = to[dof::kLKnee] = -20.0f;
  }
  int limit(const bool skip[2]) {
    glm::vec3 a0[2], a1[2];
    ankle_positions(human_skeleton(), from, last.height, BodyFrame(last.x, last.y, last.heading), a0);
    ankle_positions(human_skeleton(), to, now.height, BodyFrame(now.x, now.y, now.heading), a1);
    return limit_drawn_travel(human_skeleton(), last, from, a0, now, to, a1, skip);
  }
};

TEST(DrawnTravel, ALegWhoseBlendCarriesItsAnkleTooFastIsHeldBack) {
  Swing s;
  glm::vec3 a0[2], a1[2];
  ankle_positions(human_skeleton(), s.from, 0.93f, BodyFrame(10.0f, 5.0f, 30.0f), a0);
  ankle_positions(human_skeleton(), s.to, 0.93f, BodyFrame(10.0f, 5.0f, 30.0f), a1);
  ASSERT_LE(glm::length(a1[0] - a0[0]), kAnklePastPelvisM) << "the chord is within the frame's bounds";
  ASSERT_GT(fastest_third(s.from, s.last, s.to, s.now, 0).rel, 0.6f) << "and the drawn frame pops";
  const auto planned = s.to;
  const bool skip[2] = {false, false};
  EXPECT_EQ(s.limit(skip), 1);
  const Drawn d = fastest_third(s.from, s.last, s.to, s.now, 0);
  EXPECT_LE(d.rel, kDrawnPopRelM + 1e-3f);
  EXPECT_GT(d.rel, kDrawnPopRelM - 0.03f) << "held back no more than it must";
  EXPECT_LT(s.to[dof::kRKnee], -60.0f) << "still most of the way";
  for (int k = dof::kLHip; k < dof::kCount; ++k) EXPECT_EQ(s.to[static_cast<std::size_t>(k)], planned[static_cast<std::size_t>(k)]);
}

// A leg the caller keeps (a planted foot, a kick's contact) is not moved,
// nor a leg whose blend is slow.
TEST(DrawnTravel, AKeptOrSlowLegIsLeftAlone) {
  {
    Swing s;
    const auto planned = s.to;
    const bool skip[2] = {true, false};
    EXPECT_EQ(s.limit(skip), 0);
    EXPECT_EQ(s.to, planned);
  }
  Swing s;
  s.to[dof::kRHip] = 0.0f;
  s.to[dof::kRKnee] = -30.0f;
  const auto planned = s.to;
  const bool skip[2] = {false, false};
  EXPECT_EQ(s.limit(skip), 0);
  EXPECT_EQ(s.to, planned);
}

// With the body running at 9 m/s (0.45 m a frame) and turning, the same
// swing is held back until each third keeps within both bounds, over the
// grass and about the pelvis.
TEST(DrawnTravel, ARunningBodysSwingKeepsWithinBothBounds) {
  Swing s;
  s.now = DrawnRoot{10.0f + 0.45f * 0.866f, 5.0f + 0.45f * 0.5f, 0.95f, 38.0f};
  const bool skip[2] = {false, false};
  EXPECT_EQ(s.limit(skip) & 1, 1);
  const Drawn d = fastest_third(s.from, s.last, s.to, s.now, 0);
  EXPECT_LE(d.rel, kDrawnPopRelM + 1e-3f);
  EXPECT_LE(d.world, kDrawnPopM + 1e-3f);
}

}  // namespace
}  // namespace mc::anim
