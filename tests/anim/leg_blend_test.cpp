// LegBlend: a foot on the grass in two frames stays on its line in the
// drawn frames between them, one leaving or landing is raised off the
// grass; a foot in the air keeps the angle blend.
#include "anim/leg_blend.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <random>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "anim/human_skeleton.hpp"
#include "anim/leg_pose_job.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/segment_distance.hpp"
#include "proto/hello.hpp"

namespace mc::anim {
namespace {

// A player at field (x, 0) facing +x whose feet are at the given body-space
// ankles (pelvis 0.93 m up, leaning a little forward).
PlayerPose stance(float x, float right_ankle_x, float left_ankle_x, float left_ankle_h, float right_ankle_h = 0.08f,
                  float pelvis_yaw = 0.0f, float half_gap = 0.11f) {
  PlayerPose p;
  p.side = Side::Left;
  p.unum = 7;
  p.x = x;
  p.z = 0.93f;
  p.angles[dof::kPelvis] = pelvis_yaw;
  p.angles[dof::kPelvis + 1] = -6;
  LegPoseJob job;
  job.pelvis_height = p.z;
  job.feet[0].ankle_ms[0] = right_ankle_x; job.feet[0].ankle_ms[1] = right_ankle_h; job.feet[0].ankle_ms[2] = half_gap;
  job.feet[1].ankle_ms[0] = left_ankle_x; job.feet[1].ankle_ms[1] = left_ankle_h; job.feet[1].ankle_ms[2] = -half_gap;
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

// The lowest corner of one foot's box (0 right, 1 left) above the grass.
float sole(const PlayerPose& p, int side) {
  const SkeletonDef& s = human_skeleton();
  std::vector<glm::mat4> m(s.joints.size());
  LocalToModelJob fk{&s, std::span<const float>(p.angles.data(), p.angles.size()), glm::vec3(0, p.z, 0), m};
  EXPECT_TRUE(fk.Run());
  const int j = side == 0 ? kRFoot : kLFoot;
  const Segment& box = s.joints[static_cast<std::size_t>(j)].segment;
  float low = 1e9f;
  for (int c = 0; c < 8; ++c) {
    const glm::vec4 corner(box.center[0] + ((c & 1) ? 0.5f : -0.5f) * box.size[0],
                           box.center[1] + ((c & 2) ? 0.5f : -0.5f) * box.size[1],
                           box.center[2] + ((c & 4) ? 0.5f : -0.5f) * box.size[2], 1.0f);
    low = std::min(low, (m[static_cast<std::size_t>(j)] * corner).y);
  }
  return low;
}

TEST(LegBlend, APlantedFootStaysOnItsLineBetweenFrames) {
  const LegBlend legs(human_skeleton());
  ASSERT_TRUE(legs.ready());
  // The body moves 0.3 m over the planted right foot (field x 0.15); the
  // left foot swings 0.3 m up in the air.
  // The pelvis turns 12 deg over it, as in a turn.
  const PlayerPose a = stance(0.0f, 0.15f, -0.35f, 0.25f, 0.08f, -6.0f);
  const PlayerPose b = stance(0.3f, -0.15f, 0.05f, 0.22f, 0.08f, 6.0f);
  ASSERT_NEAR(ankle(a, 0).x, ankle(b, 0).x, 1e-3f);
  float blend_error = 0;
  for (float t : {1.0f / 3, 0.5f, 2.0f / 3}) {
    const PlayerPose blended = angle_blend(a, b, t);
    auto across = [&](const PlayerPose& p) { return std::hypot(ankle(p, 0).x - ankle(a, 0).x, ankle(p, 0).z - ankle(a, 0).z); };
    blend_error = std::max(blend_error, across(blended));
    PlayerPose o = blended;
    legs.apply(a, b, t, o);
    // A swing of at most kMaxSwingDeg takes it (nearly) all the way.
    EXPECT_LT(across(o), 0.2f * across(blended)) << "t " << t;
    EXPECT_LT(across(o), 0.003f) << "t " << t;
    // Only the thigh turns, and little; the swinging leg keeps the blend's arc.
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(o.angles[static_cast<std::size_t>(dof::kRHip + k)], blended.angles[static_cast<std::size_t>(dof::kRHip + k)],
                  LegBlend::kMaxSwingDeg + 0.01f);
    for (int k = dof::kRKnee; k < dof::kRAnkle + 2; ++k)
      EXPECT_EQ(o.angles[static_cast<std::size_t>(k)], blended.angles[static_cast<std::size_t>(k)]) << "dof " << k;
    for (int k = dof::kLHip; k < dof::kLAnkle + 2; ++k)
      EXPECT_EQ(o.angles[static_cast<std::size_t>(k)], blended.angles[static_cast<std::size_t>(k)]) << "dof " << k;
  }
  // Without it the planted foot would move (what the test is about).
  EXPECT_GT(blend_error, 0.012f);
}

TEST(LegBlend, ALeavingFootRisesAtOnceAndALandingOneComesDownSteeply) {
  const LegBlend legs(human_skeleton());
  // The right foot leaves the grass behind the body: on it in a, 0.2 m
  // forward and 0.06 m up in b (a low running swing, which the angle blend
  // drags over the grass).
  const PlayerPose a = stance(0.0f, -0.38f, 0.2f, 0.25f);
  const PlayerPose b = stance(0.3f, -0.42f, 0.1f, 0.22f, 0.15f);
  ASSERT_LT(sole(a, 0), LegBlend::kContactM);
  ASSERT_GT(sole(b, 0), LegBlend::kContactM);
  const float t = 1.0f / 3;
  const PlayerPose blended = angle_blend(a, b, t);
  PlayerPose lift = blended;
  legs.apply(a, b, t, lift);
  // The blend gives the sole a third of its rise, the target 5/9 of it:
  // the ankle goes up towards the difference as far as a swing of the leg
  // about the hip takes it (the leg keeps its length: a leg 25 deg behind
  // the hip gets about a fifth of the way), and the sole with it. The
  // target is also held back across the grass (the next test), which on a
  // leg behind the hip raises the ankle too: at most that shift's
  // tan(25 deg) more.
  const float rise = sole(b, 0) - sole(a, 0);
  ASSERT_GT(rise, 0.015f);
  const float want = rise * (5.0f / 9 - 1.0f / 3);
  const float held_back = LegBlend::kAcrossEase * (2.0f / 9) * LegBlend::kAcrossWayM;
  EXPECT_GT(ankle(lift, 0).y - ankle(blended, 0).y, 0.15f * want);
  EXPECT_LT(ankle(lift, 0).y - ankle(blended, 0).y, 1.01f * want + 0.47f * held_back);
  EXPECT_GT(sole(lift, 0), sole(blended, 0));
  // Landing, the same frames the other way round: it stays up longer.
  PlayerPose land = angle_blend(b, a, 1.0f - t);
  const PlayerPose land_blend = land;
  legs.apply(b, a, 1.0f - t, land);
  EXPECT_GT(ankle(land, 0).y - ankle(land_blend, 0).y, 0.15f * want);
  // The left foot, in the air in both, keeps the blend.
  for (int k = dof::kLHip; k < dof::kLAnkle + 2; ++k)
    EXPECT_EQ(lift.angles[static_cast<std::size_t>(k)], blended.angles[static_cast<std::size_t>(k)]) << "dof " << k;
}

TEST(LegBlend, ALeavingFootStartsAcrossTheGrassSlowlyAndALandingOneEndsSlowly) {
  const LegBlend legs(human_skeleton());
  // The frames above: the right foot leaves the grass and moves 0.26 m
  // forward over the frame (about the root it moves 4 cm: the ease is not
  // bounded by the travel).
  const PlayerPose a = stance(0.0f, -0.38f, 0.2f, 0.25f);
  const PlayerPose b = stance(0.3f, -0.42f, 0.1f, 0.22f, 0.15f);
  const float way = ankle(b, 0).x - ankle(a, 0).x;
  ASSERT_GT(way, LegBlend::kAcrossWayM);
  // A third of the way in, the target is behind the blend by k t (1 - t)
  // of the way taken (kAcrossWayM): 1.7 cm. The swing of at most 1 deg
  // about the hip, which also lifts the foot, takes the ankle part of it.
  const float t = 1.0f / 3;
  const float want = LegBlend::kAcrossEase * t * (1 - t) * LegBlend::kAcrossWayM;
  const PlayerPose blended = angle_blend(a, b, t);
  PlayerPose lift = blended;
  legs.apply(a, b, t, lift);
  EXPECT_LT(ankle(lift, 0).x - ankle(blended, 0).x, -0.3f * want);
  EXPECT_GT(ankle(lift, 0).x - ankle(blended, 0).x, -1.01f * want);
  // Landing (the frames the other way round), two thirds of the way in:
  // nearer its spot than the blend.
  const PlayerPose land_blend = angle_blend(b, a, 1.0f - t);
  PlayerPose land = land_blend;
  legs.apply(b, a, 1.0f - t, land);
  EXPECT_LT(ankle(land, 0).x - ankle(land_blend, 0).x, -0.3f * want);
  // A foot whose ankle travels kApartTravelM or more about the root over
  // the frame is not eased across the grass (the ease would add to a
  // pop's travel): b's right ankle 0.5 m further forward about the root.
  const PlayerPose fast = stance(0.3f, 0.12f, 0.1f, 0.22f, 0.15f);
  ASSERT_GT(sole(fast, 0), LegBlend::kContactM);
  ASSERT_GE((ankle(fast, 0).x - fast.x) - (ankle(a, 0).x - a.x), LegBlend::kApartTravelM);
  const PlayerPose fast_blend = angle_blend(a, fast, t);
  PlayerPose fast_lift = fast_blend;
  legs.apply(a, fast, t, fast_lift);
  EXPECT_GT(ankle(fast_lift, 0).x - ankle(fast_blend, 0).x, -0.3f * want);
}

// How far apart the legs' boxes are (centre line to centre line, less half
// the wider box): the smallest of thighs, shins and feet (anim-quality's
// clearance).
float legs_apart(const PlayerPose& p) {
  const SkeletonDef& s = human_skeleton();
  std::vector<glm::mat4> m(s.joints.size());
  LocalToModelJob fk{&s, std::span<const float>(p.angles.data(), p.angles.size()), glm::vec3(0, p.z, 0), m};
  EXPECT_TRUE(fk.Run());
  auto line = [&](int j, glm::vec3& from, glm::vec3& to, float& half_width) {
    const Segment& b = s.joints[static_cast<std::size_t>(j)].segment;
    const glm::vec3 h(0.5f * b.size[0], 0.5f * b.size[1], 0.5f * b.size[2]);
    const int axis = h.x >= h.y && h.x >= h.z ? 0 : h.y >= h.z ? 1 : 2;
    glm::vec3 e(0.0f);
    e[axis] = h[axis];
    const glm::vec3 c(b.center[0], b.center[1], b.center[2]);
    from = glm::vec3(m[static_cast<std::size_t>(j)] * glm::vec4(c - e, 1.0f));
    to = glm::vec3(m[static_cast<std::size_t>(j)] * glm::vec4(c + e, 1.0f));
    half_width = std::max(h[(axis + 1) % 3], h[(axis + 2) % 3]);
  };
  float apart = 1e9f;
  for (const auto& [r, l] : {std::pair{kRThigh, kLThigh}, std::pair{kRShin, kLShin}, std::pair{kRFoot, kLFoot}}) {
    glm::vec3 p1, q1, p2, q2;
    float w1 = 0, w2 = 0;
    line(r, p1, q1, w1);
    line(l, p2, q2, w2);
    apart = std::min(apart, segment_distance(p1, q1, p2, q2) - std::max(w1, w2));
  }
  return apart;
}

// A right leg swinging from behind to in front of a left one planted close
// to the body's midline: apart in both frames, through the other leg in
// the plain blend between them.
struct PassingLegs {
  PlayerPose a = stance(0.0f, -0.15f, 0.0f, 0.08f, 0.16f, 0.0f, 0.005f);
  PlayerPose b = stance(0.15f, 0.15f, 0.0f, 0.08f, 0.16f, 0.0f, 0.005f);
};

TEST(LegBlend, ALegSwingingPastTheOtherTurnsOutOfItsWay) {
  const PassingLegs legs;
  ASSERT_GT(legs_apart(legs.a), 0.0f);
  ASSERT_GT(legs_apart(legs.b), 0.0f);
  const PlayerPose plain = angle_blend(legs.a, legs.b, 0.5f);
  ASSERT_LT(legs_apart(plain), -0.005f) << "the case must pass the legs through each other";
  const LegBlend blend(human_skeleton());
  PlayerPose drawn = plain;
  blend.apply(legs.a, legs.b, 0.5f, drawn);
  EXPECT_GT(legs_apart(drawn), 0.0f);
  // Only the leg in the air turned: the planted left foot stays put.
  EXPECT_LT(glm::length(ankle(drawn, 1) - ankle(plain, 1)), 1e-4f);
  EXPECT_GT(glm::length(ankle(drawn, 0) - ankle(plain, 0)), 0.005f);
}

// Two real frames (game 1, seq 2428-2429, slot 18, 1.6 m/s): both feet in
// the air, apart in both frames, the feet's centre lines 9 mm inside their
// distance a third of the way between them. Turned out, away from the other
// hip, the feet went 3.8 cm inside: the nearest points moved towards each
// other. They part along the line between those points.
PlayerPose real_frame(float x, float y, float z, float heading, std::initializer_list<float> angles) {
  PlayerPose p;
  p.side = Side::Left;
  p.unum = 7;
  p.x = x;
  p.y = y;
  p.z = z;
  p.heading = heading;
  std::copy(angles.begin(), angles.end(), p.angles.begin());
  return p;
}

// Two frames of a real game whose feet, apart at both, meet in the blend.
struct FeetMeeting {
  PlayerPose a = real_frame(
      -32.95f, -19.68f, 0.96f, 134.5055f,
      {0.39f,  -1.0f,  0.04f,  -0.45f, -0.6f,   -0.35f,  2.17f,   0.54f,  -0.3f,  3.16f,  0.54f,  -0.3f,
       -3.67f, -18.63f, 0.09f, 11.88f, 0.29f,   -0.3f,   -2.68f,  12.57f, 0.09f,  11.88f, 0.29f,  -0.3f,
       -1.39f, -30.2f, -38.07f, -32.24f, 16.23f, 24.45f, -14.26f, -23.12f, -34.11f, -11.45f, 10.29f, 27.42f});
  PlayerPose b = real_frame(
      -32.97f, -19.6f, 0.95f, 135.4945f,
      {1.38f,  -1.0f,  1.03f,  -3.42f, -1.59f,  -1.34f,  4.15f,   0.54f,  -0.3f,  7.12f,  0.54f,  -0.3f,
       -7.63f, -12.69f, 0.09f, 11.88f, 0.29f,   -0.3f,   0.29f,   12.57f, 0.09f,  11.88f, 0.29f,  -0.3f,
       33.26f, -11.39f, -14.31f, -61.94f, 28.11f, 0.69f, -19.21f, -26.09f, -33.12f, -11.45f, 12.27f, 28.41f});
  // The blend at `t` as the clients draw it before their step.
  PlayerPose blended(float t) const {
    PlayerPose drawn = angle_blend(a, b, t);
    drawn.heading = a.heading + (b.heading - a.heading) * t;
    drawn.y = a.y + (b.y - a.y) * t;
    return drawn;
  }
};

TEST(LegBlend, FeetThatMeetInTheBlendPartAlongTheLineBetweenThem) {
  const FeetMeeting m;
  const PlayerPose& a = m.a;
  const PlayerPose& b = m.b;
  ASSERT_GT(sole(a, 0), LegBlend::kContactM);
  ASSERT_GT(sole(a, 1), LegBlend::kContactM);
  ASSERT_GT(sole(b, 0), LegBlend::kContactM);
  ASSERT_GT(sole(b, 1), LegBlend::kContactM);
  ASSERT_GT(legs_apart(a), 0.0f);
  ASSERT_GT(legs_apart(b), 0.0f);
  ASSERT_LT(legs_apart(angle_blend(a, b, 1.0f / 3.0f)), -0.005f) << "the case must bring the feet together";
  const LegBlend blend(human_skeleton());
  for (float t : {1.0f / 3.0f, 0.5f, 2.0f / 3.0f}) {
    PlayerPose drawn = m.blended(t);
    blend.apply(a, b, t, drawn);
    EXPECT_GE(legs_apart(drawn), 0.0f) << t;
  }
}

TEST(LegBlend, ItTellsTheWayItPartedTheFeet) {
  // keep_legs_apart_drawn reads the way to find where it turns fast.
  const FeetMeeting m;
  const LegBlend blend(human_skeleton());
  const float t = 1.0f / 3.0f;
  PlayerPose told = m.blended(t), untold = m.blended(t);
  glm::vec3 way(1.0f);
  blend.apply(m.a, m.b, t, told, &way);
  blend.apply(m.a, m.b, t, untold);
  EXPECT_GT(glm::length(way), 1e-3f);  // the first leg's nearest point from the other's
  for (int d = 0; d < dof::kCount; ++d) EXPECT_EQ(told.angles[d], untold.angles[d]) << d;  // told, not changed
  // Legs apart (frame a drawn from itself): nothing parted, no way.
  PlayerPose still = m.a;
  way = glm::vec3(1.0f);
  blend.apply(m.a, m.a, 0.5f, still, &way);
  EXPECT_EQ(way, glm::vec3(0.0f));
}

TEST(LegBlend, TheTurnOutGrowsFromNothingAtEitherFrame) {
  const PassingLegs legs;
  const LegBlend blend(human_skeleton());
  float last_turn = 0;
  for (float t : {0.02f, 0.08f, 0.98f}) {
    const PlayerPose plain = angle_blend(legs.a, legs.b, t);
    PlayerPose drawn = plain;
    blend.apply(legs.a, legs.b, t, drawn);
    // The thigh's extra turn stays within kApartSpeedDeg's room at this t.
    float turn = 0;
    for (int k = 0; k < 3; ++k)
      turn = std::max(turn, std::fabs(drawn.angles[dof::kRHip + k] - plain.angles[dof::kRHip + k]));
    EXPECT_LE(turn, LegBlend::kApartSpeedDeg * std::min(t, 1 - t) * 1.5f + 0.2f) << t;
    last_turn = turn;
  }
  EXPECT_LT(last_turn, 1.7f);
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

// A hello from an untrusted server may give a thigh's limit upside down:
// it is read as the quantizer reads it ([lo, max(lo, hi)]), not handed to
// std::clamp (whose result is then undefined).
TEST(LegBlend, AThighLimitGivenUpsideDownIsReadAsTheQuantizerReadsIt) {
  SkeletonDef s = human_skeleton();
  s.joints[static_cast<std::size_t>(kRThigh)].limits[0] = {10.0f, -10.0f};  // flexion
  const LegBlend legs(s);
  ASSERT_TRUE(legs.ready());
  const PlayerPose a = stance(0.0f, 0.15f, -0.35f, 0.25f, 0.08f, -6.0f);
  const PlayerPose b = stance(0.3f, -0.15f, 0.05f, 0.22f, 0.08f, 6.0f);
  PlayerPose o = angle_blend(a, b, 0.5f);
  legs.apply(a, b, 0.5f, o);
  EXPECT_EQ(o.angles[static_cast<std::size_t>(dof::kRHip)], 10.0f);
  for (float v : o.angles) EXPECT_TRUE(std::isfinite(v));
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

// The drawn-leg check's gate takes the plain blend's clearance roughly
// (keep_legs_apart_drawn): it must be within a tenth of its margin of the
// exact one, legs far apart, crossing and through each other alike, over
// every angle the joints allow (taken at random within their limits).
TEST(LegBlend, ItsRoughClearanceIsWithinItsMarginOfTheExactOne) {
  const SkeletonDef& s = human_skeleton();
  const LegBlend legs(s);
  ASSERT_TRUE(legs.ready());
  std::mt19937 rng(39);
  auto random_pose = [&] {
    PlayerPose p;
    std::size_t d = 0;
    for (const JointDef& j : s.joints)
      for (std::size_t k = 0; k < j.dofs.size(); ++k, ++d) {
        const auto& lim = j.limits[k];
        p.angles[d] = std::uniform_real_distribution<float>(std::min(lim[0], lim[1]), std::max(lim[0], lim[1]))(rng);
      }
    return p;
  };
  double worst = 0;
  int through = 0, apart = 0;
  for (int i = 0; i < 20000; ++i) {
    const PlayerPose a = random_pose(), b = random_pose();
    const float t = i % 7 == 0 ? 0.5f : std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    PlayerPose o = a;
    for (std::size_t k = 0; k < o.angles.size(); ++k) o.angles[k] = a.angles[k] + (b.angles[k] - a.angles[k]) * t;
    const float exact = legs.clearance(o);
    const float rough = legs.rough_clearance(a.angles.data(), b.angles.data(), t);
    ASSERT_TRUE(std::isfinite(exact) && std::isfinite(rough)) << i;
    worst = std::max(worst, static_cast<double>(std::fabs(rough - exact)));
    through += exact < 0.0f;
    apart += exact > 0.1f;
  }
  EXPECT_LT(worst, 0.1 * LegBlend::kRoughClearanceM);
  // Both kinds were there to be measured.
  EXPECT_GT(through, 500);
  EXPECT_GT(apart, 1000);
}

TEST(LegBlend, ItsRoughClearanceIsNaNWhereItCannotTell) {
  const LegBlend legs(human_skeleton());
  PlayerPose a, b;
  a.angles[dof::kRKnee] = 2e6f;  // past rough_sincos_deg's range
  EXPECT_TRUE(std::isnan(legs.rough_clearance(a.angles.data(), b.angles.data(), 0.5f)));
  a.angles[dof::kRKnee] = NAN;
  EXPECT_TRUE(std::isnan(legs.rough_clearance(a.angles.data(), b.angles.data(), 0.0f)));
  // Without legs there is nothing to be near: as clearance(), no bound.
  SkeletonDef none;
  none.joints.push_back(JointDef{"root", -1, {0, 0, 0}, "y", {{-180, 180}}, {}});
  EXPECT_EQ(LegBlend(none).rough_clearance(a.angles.data(), b.angles.data(), 0.5f), INFINITY);
}

// The clients' vectors (proto/SPEC.md 4.7, step 2): pairs of frames, a
// playhead and the blended pose, with the angles this step makes of it.
// tests/web/feet.test.mjs checks the page's implementation against the same
// file. MATCHCAST_WRITE_GOLDEN=1 writes it anew (after a change to the step
// that SPEC.md describes too).
TEST(LegBlend, GoldenVectorsForTheClients) {
  const std::string path = std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/feet_v1.json";
  const SkeletonDef& skel = human_skeleton();
  const auto dofs = static_cast<std::size_t>(skel.dof_count());
  const LegBlend legs(skel);
  // Written to 4 decimals (0.1 mm, 0.0001 deg), and read back so that the
  // step sees exactly what the file says.
  auto round4 = [](float v) { return std::round(static_cast<double>(v) * 1e4) / 1e4; };
  auto to_json = [&](const PlayerPose& p) {
    std::vector<double> angles;
    for (std::size_t k = 0; k < dofs; ++k) angles.push_back(round4(p.angles[k]));
    return nlohmann::json{{"x", round4(p.x)}, {"y", round4(p.y)}, {"z", round4(p.z)}, {"heading", round4(p.heading)}, {"angles", angles}};
  };
  auto from_json = [&](const nlohmann::json& j) {
    PlayerPose p;
    p.side = Side::Left;
    p.unum = 7;
    p.x = j["x"].get<float>();
    p.y = j["y"].get<float>();
    p.z = j["z"].get<float>();
    p.heading = j["heading"].get<float>();
    for (std::size_t k = 0; k < dofs; ++k) p.angles[k] = j["angles"][k].get<float>();
    return p;
  };
  auto step = [&](const nlohmann::json& c) {
    PlayerPose out = from_json(c["drawn"]);
    legs.apply(from_json(c["a"]), from_json(c["b"]), c["t"].get<float>(), out);
    return std::vector<float>(out.angles.begin(), out.angles.begin() + static_cast<long>(dofs));
  };

  if (std::getenv("MATCHCAST_WRITE_GOLDEN") != nullptr) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    auto in = [&](float lo, float hi) { return lo + (hi - lo) * u01(rng); };
    nlohmann::json cases = nlohmann::json::array();
    for (int i = 0; i < 80; ++i) {
      // Each foot planted (ankle 8 cm up), or 12-20 cm up in the air, in each frame.
      auto height = [&] { return u01(rng) < 0.5f ? 0.08f : in(0.12f, 0.2f); };
      PlayerPose a = stance(in(-1, 1), in(-0.35f, 0.25f), in(-0.35f, 0.25f), height(), height(), in(-8, 8));
      PlayerPose b = stance(a.x + in(0, 0.4f), in(-0.35f, 0.25f), in(-0.35f, 0.25f), height(), height(), in(-8, 8));
      if (i >= 48 && i < 72) {
        // Cases 48-71: a right leg in the air swinging past a left one near
        // the midline (the second part of the step, the legs kept apart);
        // 64-71 swing far enough for the ankle's travel to bound the turn.
        const bool far = i >= 64;
        const float gap = in(0.0f, 0.02f), left = in(-0.1f, 0.1f), left_h = height();
        a = stance(in(-1, 1), far ? in(-0.26f, -0.22f) : in(-0.2f, -0.1f), left, left_h, in(0.12f, 0.2f), in(-8, 8), gap);
        b = stance(a.x + in(0.1f, 0.3f), far ? in(0.18f, 0.22f) : in(0.1f, 0.18f), left, left_h, in(0.12f, 0.2f),
                   in(-8, 8), gap);
      }
      if (i >= 72) {
        // Cases 72-79: the same swing past a planted left leg, the right foot
        // landing (on the grass in b only) or leaving (in a only): it may
        // turn out of the way by 1 - t or t however low the blend draws it.
        const bool landing = i % 2 == 0;
        const float gap = in(0.0f, 0.02f), left = in(-0.1f, 0.1f);
        const float up_a = landing ? in(0.12f, 0.2f) : 0.08f, up_b = landing ? 0.08f : in(0.12f, 0.2f);
        a = stance(in(-1, 1), in(-0.2f, -0.1f), left, 0.08f, up_a, in(-8, 8), gap);
        b = stance(a.x + in(0.1f, 0.3f), in(0.1f, 0.18f), left, 0.08f, up_b, in(-8, 8), gap);
      }
      a.y = in(-1, 1);
      b.y = a.y + in(-0.1f, 0.1f);
      a.heading = in(-180, 180);
      b.heading = a.heading + in(-15, 15);
      // Half the cases keep the feet where they were, as a planted foot does.
      if (i % 2 == 0 && i < 48) b.angles = a.angles, b.x = a.x + 0.01f;
      const auto t = static_cast<float>(round4(i % 4 == 0 ? 1.0f / 3 : i % 4 == 1 ? 0.5f : i % 4 == 2 ? 2.0f / 3 : in(0.05f, 0.95f)));
      PlayerPose drawn = angle_blend(a, b, t);  // SPEC 4.7 step 1
      drawn.y = a.y + (b.y - a.y) * t;
      drawn.heading = a.heading + (b.heading - a.heading) * t;
      nlohmann::json c{{"t", round4(t)}, {"a", to_json(a)}, {"b", to_json(b)}, {"drawn", to_json(drawn)}};
      std::vector<double> out;
      for (float v : step(c)) out.push_back(round4(v));
      c["out"] = out;
      cases.push_back(c);
    }
    // One case a line.
    std::ofstream f(path);
    f << "{\"about\": \"proto/SPEC.md 4.7 step 2: each case's drawn pose (frames a and b blended at t) becomes out "
         "(its angles) for this skeleton\",\n\"skeleton\": "
      << proto::skeleton_to_json(skel).dump() << ",\n\"cases\": [\n";
    for (std::size_t i = 0; i < cases.size(); ++i) f << cases[i].dump() << (i + 1 < cases.size() ? ",\n" : "\n");
    f << "]}\n";
    GTEST_SKIP() << "wrote " << path;
  }
  std::ifstream file(path);
  ASSERT_TRUE(file.good()) << path;
  const nlohmann::json want = nlohmann::json::parse(file);
  ASSERT_EQ(want["cases"].size(), 80u);
  int moved = 0, apart = 0, on_the_way = 0;
  for (std::size_t i = 0; i < want["cases"].size(); ++i) {
    const auto& c = want["cases"][i];
    const std::vector<float> got = step(c);
    ASSERT_EQ(c["out"].size(), got.size());
    bool changed = false;
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_NEAR(c["out"][k].get<double>(), got[k], 1e-3) << "case " << i << " dof " << k;
      changed = changed || std::fabs(got[k] - c["drawn"]["angles"][k].get<float>()) > 1e-3f;
    }
    moved += changed;
    if (i >= 48) apart += changed;
    if (i >= 72) on_the_way += changed;
  }
  EXPECT_GT(moved, 12);      // the vectors exercise the step
  EXPECT_GE(apart, 8);       // and its second part
  EXPECT_GE(on_the_way, 4);  // with a foot leaving or landing
}

}  // namespace
}  // namespace mc::anim
