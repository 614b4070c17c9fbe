// keep_legs_apart_drawn: legs that are apart at both frames but pass
// through each other as the clients draw the frame between them
// (LegBlend, proto/SPEC.md 4.7) are turned apart at the frame (at the hip,
// out or less far forward, or a swing that crosses low lifted with its
// knee); the planted leg
// stays, the joints keep within their speed limits, and frames whose blend
// is clear are left alone.
#include "anim/drawn_leg_clearance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "anim/grid_rounding.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/leg_blend.hpp"
#include "anim/limb_clearance.hpp"
#include "anim/player_animation.hpp"
#include "proto/quantizer.hpp"

namespace mc::anim {
namespace {

constexpr float kPelvisH = 1.05f;  // feet off the grass: a flight phase

// The arms held out from the body, as the animator holds them clear of the
// thighs (keep_hands_off_thighs), so that a thigh turned out keeps off them.
void arms_out(std::array<float, dof::kCount>& a) {
  a[dof::kRShoulder + 1] = -20.0f;  // the right arm abducts towards -X
  a[dof::kLShoulder + 1] = 20.0f;
}

// A stride with both legs swung in towards the midline (each hip adducted
// `in` deg): the right leg from `flex` deg forward to as far back, the left
// the other way. Half-way both hang side by side, knees together.
std::array<float, dof::kCount> stride(float flex, float in) {
  std::array<float, dof::kCount> a{};
  a[dof::kRHip] = flex;
  a[dof::kRHip + 1] = in;  // the right leg adducts towards +X
  a[dof::kLHip] = -flex;
  a[dof::kLHip + 1] = -in;  // the left towards -X
  arms_out(a);
  return a;
}

PlayerPose pose(const std::array<float, dof::kCount>& a) {
  PlayerPose p;
  p.x = 10.0f;
  p.y = -5.0f;
  p.z = kPelvisH;
  p.heading = 30.0f;
  std::copy(a.begin(), a.end(), p.angles.begin());
  return p;
}

struct Case {
  LegBlend legs{human_skeleton()};
  std::array<float, dof::kCount> last_angles = stride(16.0f, 6.0f);
  PlayerPose last = pose(last_angles);
  std::array<float, dof::kCount> a = stride(-16.0f, 6.0f);
  DrawnRoot now{10.0f, -5.0f, kPelvisH, 30.0f};
  float drawn() const { return drawn_leg_clearance(legs, last, now, a); }
};

// The legs' least clearance as drawn at `points` points of the frame (the
// clients' blend, proto/SPEC.md 4.7 step 1, then their step 2): what a
// display shows, whatever its phase.
// The legs' clearance as drawn at `t` of the frame.
float drawn_point(const LegBlend& legs, const PlayerPose& pa, const PlayerPose& pb, float t) {
  PlayerPose o = pa;
  o.x += (pb.x - pa.x) * t;
  o.y += (pb.y - pa.y) * t;
  o.z += (pb.z - pa.z) * t;
  o.heading += std::remainder(pb.heading - pa.heading, 360.0f) * t;
  for (std::size_t k = 0; k < o.angles.size(); ++k) o.angles[k] += (pb.angles[k] - pa.angles[k]) * t;
  legs.apply(pa, pb, t, o);
  return legs.clearance(o);
}

float densely_drawn(const LegBlend& legs, const PlayerPose& pa, const PlayerPose& pb, int points = 600) {
  float least = INFINITY;
  for (int n = 1; n <= points; ++n)
    least = std::min(least, drawn_point(legs, pa, pb, static_cast<float>(n) / static_cast<float>(points)));
  return least;
}

TEST(KeepLegsApartDrawn, TheDrawnClearanceIsTheLeastAnywhereInTheFrame) {
  // Legs that pass each other at different speeds and places in the frame:
  // the least clearance is found between the checked points too, within a
  // millimetre of the dense one (a display may draw the frame at any phase).
  for (const float flex : {8.0f, 12.0f, 20.0f, 30.0f})
    for (const float in : {6.0f, 12.0f, 16.0f}) {
      Case c;
      c.last_angles = stride(flex, in);
      c.last = pose(c.last_angles);
      c.a = stride(-flex * 0.5f, in);
      const float dense = densely_drawn(c.legs, c.last, pose(c.a));
      EXPECT_NEAR(c.drawn(), dense, 0.001f) << flex << " " << in;
    }
}

// A pose of a real game: root (x, y, height), heading and every angle.
PlayerPose game_pose(float x, float y, float z, float heading, const std::array<float, dof::kCount>& a) {
  PlayerPose p = pose(a);
  p.x = x;
  p.y = y;
  p.z = z;
  p.heading = heading;
  return p;
}

TEST(KeepLegsApartDrawn, ADipBesideTheNearestCheckedPointIsFoundToo) {
  // Game 1 seq 2193 -> 2194, right 2, turning as he runs at 5.7 m/s: the
  // clients' step bends the drawn clearance into two dips, 1.0 cm at t =
  // 0.465 and, from t = 0.61 to 0.648, the feet through each other (3 cm
  // deep at 0.645). Searched about the nearest checked point alone (t =
  // 1/2), the check found the first and let the frame be; a display at
  // phase 0.85 drew the feet 0.4 mm inside each other (t = 0.617).
  const PlayerPose last = game_pose(
      14.62f, 2.73f, 0.94f, -81.099f,
      {-3.57f,  -1.0f,   -0.95f,  7.47f,   -1.59f, 1.63f,   20.98f, 1.53f,   -0.3f,   30.88f, 0.54f,  -0.3f,
       6.23f,   -13.68f, 0.09f,   19.8f,   0.29f,  -0.3f,   -17.53f, 13.56f, 0.09f,   19.8f,  0.29f,  -0.3f,
       -26.14f, 20.29f,  40.14f,  -11.45f, 13.26f, -28.02f, 23.36f,  6.58f,  14.4f,   -45.11f, 24.15f, 0.69f});
  const std::array<float, dof::kCount> a = {
      -4.56f,  -1.99f,  -0.95f,  11.43f,  -2.58f, 0.64f,   29.89f,  2.52f,   -0.3f,  44.74f,  1.53f,  -0.3f,
      13.16f,  -15.66f, 0.09f,   36.63f,  0.29f,  -0.3f,   -32.38f, 15.54f,  0.09f,  36.63f,  0.29f,  -0.3f,
      13.46f,  25.24f,  40.14f,  -66.89f, 33.06f, -16.14f, 4.55f,   12.52f,  25.29f, -49.07f, 33.06f, -9.21f};
  const DrawnRoot now{14.74f, 2.47f, 0.93f, -72.198f};
  const LegBlend legs(human_skeleton());
  const float dense = densely_drawn(legs, last, game_pose(now.x, now.y, now.height, now.heading, a));
  ASSERT_LT(dense, 0.0f);
  EXPECT_NEAR(drawn_leg_clearance(legs, last, now, a), dense, 0.001f);
}

TEST(KeepLegsApartDrawn, FeetTheClientsStepLetsThroughInASliverOfTheFrameAreTurnedApart) {
  // Game 2 seq 11922 -> 11923, left 3, in flight at 6 m/s: the clients'
  // step holds the feet 7.5 mm apart up to t = 0.199, but the way it
  // parts them swings 75 deg as their centre lines pass, and from 0.199 to
  // 0.204 it lets them 1.1 cm into each other. Searched over the
  // clearance alone, the check found 7.5 mm and let the frame be; a
  // display at phase 0.6 drew the feet through each other (t = 0.2).
  const PlayerPose last = game_pose(
      -14.83f, 19.34f, 0.94f, 92.967f,
      {-2.58f,  -1.0f,   -0.95f, 6.48f,   -0.6f,  0.64f,   -13.67f, 0.54f,  -0.3f,  -20.6f, 0.54f,   -0.3f,
       5.24f,   -12.69f, 0.09f,  11.88f,  0.29f,  -0.3f,   -11.59f, 12.57f, 0.09f,  11.88f, 0.29f,   -0.3f,
       -7.33f,  26.23f,  16.38f, -33.23f, 14.25f, -25.05f, 8.51f,   22.42f, 3.51f,  -46.1f, 33.06f,  -21.09f});
  // The frame as the animator made it, before the stream's rounding.
  std::array<float, dof::kCount> a = {
      -3.9852f, -0.8f,  -0.0535f, 8.9667f,  -1.2f,  0.0535f,  -11.7926f, 1.0f,     0.0f,    -17.6889f, 0.6f,  0.0f,
      7.9556f,  -13.0f, 0.0f,     12.0f,    0.0f,   0.0f,     -15.9556f, 13.0f,    0.0f,    12.0f,     0.0f,  0.0f,
      -14.8759f, 29.8392f, 27.1234f, -29.2078f, 16.9799f, -28.0f,
      41.2872f,  -15.0536f, 5.2141f, -92.349f,  33.0f,    19.4348f};
  const DrawnRoot now{-15.13265f, 19.3110f, 0.928172f, 104.685974f};
  const LegBlend legs(human_skeleton());
  auto next = [&] { return game_pose(now.x, now.y, now.height, now.heading, a); };
  ASSERT_LT(densely_drawn(legs, last, next(), 6000), -0.005f);
  EXPECT_LT(drawn_leg_clearance(legs, last, now, a), 0.0f);
  // Both feet in the air: the check turns a leg so that no phase of the
  // display draws the feet inside each other.
  const bool none_planted[2] = {false, false};
  std::array<float, dof::kCount> last_angles{};
  std::copy_n(last.angles.begin(), dof::kCount, last_angles.begin());
  EXPECT_TRUE(keep_legs_apart_drawn(legs, human_skeleton(), nullptr, last, last_angles, now, none_planted, a));
  EXPECT_GE(densely_drawn(legs, last, next(), 6000), 0.0f);
}

TEST(KeepLegsApartDrawn, ACandidateTurnIsPassedOverExactlyWhenTheWholeFrameDrawnSaysSo) {
  // A candidate turn is drawn only until a point comes no clearer than the
  // best so far (`beat`), in the golden-section search and where the feet's
  // way turns too: that must say what drawing the whole frame says. The
  // frames: crossing strides, and the two game frames above (a dip beside
  // the nearest checked point; the feet's way swinging as they pass).
  struct Frame {
    PlayerPose last;
    DrawnRoot now;
    std::array<float, dof::kCount> a;
  };
  std::vector<Frame> frames;
  for (const float flex : {12.0f, 20.0f, 30.0f})
    for (const float in : {6.0f, 16.0f}) {
      Case c;
      frames.push_back({pose(stride(flex, in)), c.now, stride(-flex * 0.5f, in)});
    }
  frames.push_back({game_pose(14.62f, 2.73f, 0.94f, -81.099f,
                              {-3.57f,  -1.0f,   -0.95f,  7.47f,   -1.59f, 1.63f,   20.98f, 1.53f,   -0.3f,
                               30.88f,  0.54f,   -0.3f,   6.23f,   -13.68f, 0.09f,  19.8f,  0.29f,   -0.3f,
                               -17.53f, 13.56f,  0.09f,   19.8f,   0.29f,  -0.3f,   -26.14f, 20.29f, 40.14f,
                               -11.45f, 13.26f,  -28.02f, 23.36f,  6.58f,  14.4f,   -45.11f, 24.15f, 0.69f}),
                    DrawnRoot{14.74f, 2.47f, 0.93f, -72.198f},
                    {-4.56f,  -1.99f,  -0.95f, 11.43f,  -2.58f, 0.64f,   29.89f,  2.52f,   -0.3f,
                     44.74f,  1.53f,   -0.3f,  13.16f,  -15.66f, 0.09f,  36.63f,  0.29f,   -0.3f,
                     -32.38f, 15.54f,  0.09f,  36.63f,  0.29f,  -0.3f,   13.46f,  25.24f,  40.14f,
                     -66.89f, 33.06f,  -16.14f, 4.55f,  12.52f, 25.29f,  -49.07f, 33.06f,  -9.21f}});
  frames.push_back({game_pose(-14.83f, 19.34f, 0.94f, 92.967f,
                              {-2.58f, -1.0f,   -0.95f, 6.48f,   -0.6f,  0.64f,   -13.67f, 0.54f,  -0.3f,
                               -20.6f, 0.54f,   -0.3f,  5.24f,   -12.69f, 0.09f,  11.88f, 0.29f,  -0.3f,
                               -11.59f, 12.57f, 0.09f,  11.88f,  0.29f,  -0.3f,   -7.33f, 26.23f, 16.38f,
                               -33.23f, 14.25f, -25.05f, 8.51f,  22.42f, 3.51f,   -46.1f, 33.06f, -21.09f}),
                    DrawnRoot{-15.13265f, 19.3110f, 0.928172f, 104.685974f},
                    {-3.9852f,  -0.8f,     -0.0535f, 8.9667f,   -1.2f,    0.0535f,  -11.7926f, 1.0f,  0.0f,
                     -17.6889f, 0.6f,      0.0f,     7.9556f,   -13.0f,   0.0f,     12.0f,     0.0f,  0.0f,
                     -15.9556f, 13.0f,     0.0f,     12.0f,     0.0f,     0.0f,     -14.8759f, 29.8392f, 27.1234f,
                     -29.2078f, 16.9799f,  -28.0f,   41.2872f,  -15.0536f, 5.2141f, -92.349f,  33.0f, 19.4348f}});
  const LegBlend legs(human_skeleton());
  int beaten = 0, cleared = 0;
  for (const Frame& f : frames) {
    const float whole = drawn_leg_clearance(legs, f.last, f.now, f.a);
    ASSERT_TRUE(std::isfinite(whole));
    const PlayerPose next = game_pose(f.now.x, f.now.y, f.now.height, f.now.heading, f.a);
    for (const float off : {-0.02f, -0.003f, -0.001f, -1e-5f, 0.0f, 1e-5f, 0.001f, 0.003f, 0.02f}) {
      const float beat = whole + off;
      const bool expect = whole <= beat;
      EXPECT_EQ(drawn_leg_beaten(legs, f.last, f.now, f.a, beat), expect) << whole << " " << off;
      (expect ? beaten : cleared) += 1;
      // Drawn first at `first`, that point counts too.
      for (const float first : {0.1f, 0.45f, 0.9f})
        EXPECT_EQ(drawn_leg_beaten(legs, f.last, f.now, f.a, beat, first),
                  expect || drawn_point(legs, f.last, next, first) <= beat)
            << whole << " " << off << " " << first;
    }
  }
  EXPECT_GT(beaten, 0);
  EXPECT_GT(cleared, 0);
}

TEST(KeepLegsApartDrawn, LegsThatPassThroughEachOtherInTheBlendAreTurnedApartAtTheFrame) {
  Case c;
  ASSERT_TRUE(c.legs.ready());
  // The frames keep the legs apart; the blend does not.
  ASSERT_GT(c.legs.clearance(c.last), kDrawnApartM);
  ASSERT_GT(c.legs.clearance(pose(c.a)), kDrawnApartM);
  ASSERT_LT(c.drawn(), 0.0f);
  const auto before = c.a;
  // The right foot on the grass (its leg is the one tried first when free).
  const bool right_planted[2] = {true, false};
  EXPECT_TRUE(keep_legs_apart_drawn(c.legs, human_skeleton(), nullptr, c.last, c.last_angles, c.now, right_planted, c.a));
  EXPECT_GE(c.drawn(), kDrawnApartM);
  // Only the left leg moved (its hip or knee); the planted right leg and
  // the rest stayed.
  for (int d = 0; d < dof::kCount; ++d) {
    if (d >= dof::kLHip && d <= dof::kLKnee) continue;
    EXPECT_EQ(c.a[static_cast<std::size_t>(d)], before[static_cast<std::size_t>(d)]) << d;
  }
  // Within the speed limit the animator keeps legs apart by.
  EXPECT_LT(hip_turning_too_fast(c.last_angles, c.a, kMaxLegStepDeg + kSeparateAgainDeg), 0);
}

TEST(KeepLegsApartDrawn, WithBothFeetUpTheBlendIsClearedToo) {
  Case c;
  const bool in_air[2] = {false, false};
  EXPECT_TRUE(keep_legs_apart_drawn(c.legs, human_skeleton(), nullptr, c.last, c.last_angles, c.now, in_air, c.a));
  EXPECT_GE(c.drawn(), kDrawnApartM);
}

TEST(KeepLegsApartDrawn, ABlendThatKeepsApartAndPlantedLegsAreLeftAlone) {
  // Legs swung straight, not in: apart all the way.
  Case c;
  c.last_angles = stride(20.0f, -4.0f);
  c.last = pose(c.last_angles);
  c.a = stride(-20.0f, -4.0f);
  ASSERT_GE(c.drawn(), kDrawnApartM);
  auto before = c.a;
  const bool in_air[2] = {false, false};
  EXPECT_FALSE(keep_legs_apart_drawn(c.legs, human_skeleton(), nullptr, c.last, c.last_angles, c.now, in_air, c.a));
  EXPECT_EQ(c.a, before);
  // Both feet on the grass: neither leg may move, whatever the blend.
  Case d;
  before = d.a;
  const bool planted[2] = {true, true};
  EXPECT_FALSE(keep_legs_apart_drawn(d.legs, human_skeleton(), nullptr, d.last, d.last_angles, d.now, planted, d.a));
  EXPECT_EQ(d.a, before);
}

// The left leg straight under its hip on the grass; the right swings at
// the hip from `from` deg of flexion (back < 0), its knee bent `knee_from`,
// to `to`, its knee `knee_to`, adducted `in` deg; the pelvis `height` up.
struct RightSwing {
  LegBlend legs{human_skeleton()};
  std::array<float, dof::kCount> last_angles{}, a{};
  DrawnRoot now;
  PlayerPose last;
  RightSwing(float from, float knee_from, float to, float knee_to, float in, float height)
      : now{10.0f, -5.0f, height, 30.0f} {
    last_angles[dof::kRHip] = from;
    last_angles[dof::kRHip + 1] = in;
    last_angles[dof::kRKnee] = knee_from;
    a[dof::kRHip] = to;
    a[dof::kRHip + 1] = in;
    a[dof::kRKnee] = knee_to;
    arms_out(last_angles);
    arms_out(a);
    last = at(last_angles);
  }
  PlayerPose at(const std::array<float, dof::kCount>& q) const {
    PlayerPose p = pose(q);
    p.z = now.height;
    return p;
  }
  float drawn() const { return drawn_leg_clearance(legs, last, now, a); }
  bool keep_apart() {
    const bool left_planted[2] = {false, true};
    return keep_legs_apart_drawn(legs, human_skeleton(), nullptr, last, last_angles, now, left_planted, a);
  }
  // Both frames keep the legs apart; the blend does not.
  void expect_crossing() const {
    ASSERT_GT(legs.clearance(last), kDrawnApartM);
    ASSERT_GT(legs.clearance(at(a)), kDrawnApartM);
    ASSERT_LT(drawn(), 0.0f);
  }
};

// Only dof `moved` of `a` differs from `before`.
void expect_only(int moved, const std::array<float, dof::kCount>& a, const std::array<float, dof::kCount>& before) {
  for (int d = 0; d < dof::kCount; ++d) {
    if (d == moved) continue;
    EXPECT_EQ(a[static_cast<std::size_t>(d)], before[static_cast<std::size_t>(d)]) << d;
  }
}

TEST(KeepLegsApartDrawn, ASwingThatCrossesLowLiftsItsFootWithTheKnee) {
  // From 12 deg back to 32 deg forward, adducted 10.5 deg (a step that
  // crosses in front of the planted foot), the knee bending from 20 deg
  // to 30: the swinging foot passes through the planted one (2.4 cm at the
  // deepest). No turn of the hip clears it; bending the knee further at
  // the frame lifts the foot as it passes. (Adducted 11 deg, the knee
  // cleared it by 7.7 mm while the clients' step parted the feet along
  // their nearest points; since it parts them from each other's centre
  // line, 32 deg of knee, the most the check turns, leaves 2.4 mm.
  // Adducted 11.5 deg or more, neither clears it.)
  RightSwing c(-12.0f, -20.0f, 32.0f, -30.0f, 10.5f, 1.0f);
  c.expect_crossing();
  const auto before = c.a;
  EXPECT_TRUE(c.keep_apart());
  EXPECT_GE(c.drawn(), kDrawnApartM);
  // The right knee bent further; nothing else moved.
  EXPECT_LT(c.a[dof::kRKnee], before[dof::kRKnee]);
  expect_only(dof::kRKnee, c.a, before);
  // Within the knee's speed limit since the frame before.
  EXPECT_LE(std::fabs(c.a[dof::kRKnee] - c.last_angles[dof::kRKnee]), kMaxKneeStepDeg);
}

TEST(KeepLegsApartDrawn, ASwingPastThePlantedLegReachesLessFarAtTheFrame) {
  // From 40 deg back, the knee bent 40 deg, to 16 deg forward and
  // straight, adducted 9 deg, the pelvis low (0.9 m): from 0.6 to 0.8 of
  // the frame the swinging foot grazes the planted one (5 mm into it).
  // Swung less far forward at the frame (hip flexion), the blend carries
  // it past: no turn out, about its axis or of the knee clears it.
  RightSwing c(-40.0f, -40.0f, 16.0f, 0.0f, 9.0f, 0.9f);
  c.expect_crossing();
  const auto before = c.a;
  EXPECT_TRUE(c.keep_apart());
  EXPECT_GE(c.drawn(), kDrawnApartM);
  // Less far forward, by whole steps; nothing else moved.
  EXPECT_LT(c.a[dof::kRHip], before[dof::kRHip]);
  EXPECT_EQ(std::fmod(before[dof::kRHip] - c.a[dof::kRHip], kDrawnStepDeg), 0.0f);
  expect_only(dof::kRHip, c.a, before);
  EXPECT_LT(hip_turning_too_fast(c.last_angles, c.a, kMaxLegStepDeg + kSeparateAgainDeg), 0);
}

// `p` as the stream carries it: rounded by the animator as it sends a
// frame (grid_rounding.hpp) and then by the encoder.
PlayerPose as_sent(const proto::Quantizer& grid, PlayerPose p) {
  std::array<glm::mat4, kHumanJointCount> models{};
  LocalToModelJob fk{&human_skeleton(), std::span<const float>(p.angles.data(), dof::kCount), glm::vec3(0, p.z, 0),
                     models};
  fk.joint_mask = kLegJoints;
  EXPECT_TRUE(fk.Run());
  round_legs_to_grid(grid, human_skeleton(), models.data(), p);
  return as_streamed(grid, p);
}

TEST(KeepLegsApartDrawn, TheFrameIsClearedAsTheStreamCarriesIt) {
  // The knee's crossing swing, adducted 10 deg. The turn that clears the
  // unrounded frame by 7.6 mm leaves the frame the clients receive, its
  // hip and knee rounded to the stream's 0.99-deg grid so as to keep the
  // ankle (grid_rounding.hpp), 1.2 mm through the planted leg: the check
  // turns on until that frame clears too.
  const proto::Quantizer grid(human_skeleton());
  RightSwing c(-12.0f, -20.0f, 32.0f, -30.0f, 10.0f, 1.0f);
  c.last = as_sent(grid, c.last);  // the last frame went out rounded
  std::copy_n(c.last.angles.begin(), dof::kCount, c.last_angles.begin());
  c.expect_crossing();
  const bool left_planted[2] = {false, true};
  EXPECT_TRUE(keep_legs_apart_drawn(c.legs, human_skeleton(), &grid, c.last, c.last_angles, c.now, left_planted, c.a));
  EXPECT_GE(c.drawn(), kDrawnApartM);
  const PlayerPose sent = as_sent(grid, c.at(c.a));
  EXPECT_GE(drawn_leg_clearance(c.legs, c.last, DrawnRoot{sent.x, sent.y, sent.z, sent.heading},
                                std::span<const float>(sent.angles.data(), dof::kCount)),
            kDrawnApartM);
}

TEST(KeepLegsApartDrawn, TheKneeStaysWithinItsSpeedLimit) {
  // A crossing swing from 28 deg back to 36 deg forward, adducted 12 deg,
  // its knee bent 56 deg more since the frame before (the knee's speed
  // limit, kMaxKneeStepDeg): bending it further would leave the blend
  // clearer than any other turn, but faster than a knee may turn.
  RightSwing c(-28.0f, -10.0f, 36.0f, -10.0f - kMaxKneeStepDeg, 12.0f, 1.0f);
  ASSERT_LT(c.drawn(), 0.0f);
  c.keep_apart();
  EXPECT_LE(std::fabs(c.a[dof::kRKnee] - c.last_angles[dof::kRKnee]), kMaxKneeStepDeg);
}

TEST(KeepLegsApartDrawn, TheTurnStaysWithinTheHipsSpeedLimit) {
  // The left hip already turned inwards since the frame before (as the
  // joint speed limit measures it) a degree short of the limit the
  // animator keeps legs apart by: turning it out, which would clear the
  // blend, would take it past the limit, so it is not turned out.
  Case c;
  c.last_angles[dof::kLHip] = c.a[dof::kLHip];
  c.last_angles[dof::kLHip + 1] = c.a[dof::kLHip + 1] - (kMaxLegStepDeg + kSeparateAgainDeg - 1.0f);
  ASSERT_LT(hip_turning_too_fast(c.last_angles, c.a, kMaxLegStepDeg + kSeparateAgainDeg), 0);
  ASSERT_LT(c.drawn(), 0.0f);
  const bool right_planted[2] = {true, false};
  keep_legs_apart_drawn(c.legs, human_skeleton(), nullptr, c.last, c.last_angles, c.now, right_planted, c.a);
  EXPECT_LT(hip_turning_too_fast(c.last_angles, c.a, kMaxLegStepDeg + kSeparateAgainDeg), 0);
}

TEST(KeepLegsApartDrawn, AStepABoundRefusesIsTriedAtHalfItsSize) {
  // As above, the left hip three degrees short of its limit, so that no
  // turn out is allowed (a whole step is 4 deg) and the knee is what
  // helps: bent 4, 8, 12, 16 deg the blend grows clearer each time; at 20
  // its ankle would pop as drawn. Half that step, 18 deg, does not, and
  // leaves the blend clearer than 16 deg would.
  Case c;
  c.last_angles[dof::kLHip] = c.a[dof::kLHip];
  c.last_angles[dof::kLHip + 1] = c.a[dof::kLHip + 1] - (kMaxLegStepDeg + kSeparateAgainDeg - 3.0f);
  auto out = c.a;
  out[dof::kLHip + 1] += kDrawnStepDeg;
  ASSERT_GE(hip_turning_too_fast(c.last_angles, out, kMaxLegStepDeg + kSeparateAgainDeg), 0);
  const auto before = c.a;
  auto whole_steps = c.a;
  whole_steps[dof::kLKnee] -= 4.0f * kDrawnStepDeg;
  const float after_whole_steps = drawn_leg_clearance(c.legs, c.last, c.now, whole_steps);
  ASSERT_LT(after_whole_steps, 0.0f);
  const bool right_planted[2] = {true, false};
  EXPECT_TRUE(keep_legs_apart_drawn(c.legs, human_skeleton(), nullptr, c.last, c.last_angles, c.now, right_planted, c.a));
  EXPECT_EQ(c.a[dof::kLKnee], before[dof::kLKnee] - 4.5f * kDrawnStepDeg);
  expect_only(dof::kLKnee, c.a, before);
  EXPECT_GT(c.drawn(), after_whole_steps);
}

TEST(KeepLegsApartDrawn, AThighIsNotTurnedIntoItsOwnHand) {
  // The first case with the arms hanging at the sides: the left hand
  // close by the left thigh, which a turn out would take into it.
  Case c;
  for (auto* q : {&c.a, &c.last_angles}) {
    (*q)[dof::kRShoulder + 1] = 0.0f;
    (*q)[dof::kLShoulder + 1] = 0.0f;
  }
  c.last = pose(c.last_angles);
  const float hand_before = hand_depth_in_thigh(human_skeleton(), c.a, c.last_angles, 1);
  ASSERT_GT(hand_before, -0.06f);  // closer than keep_hands_off_thighs leaves it
  ASSERT_LT(c.drawn(), 0.0f);
  const bool right_planted[2] = {true, false};
  keep_legs_apart_drawn(c.legs, human_skeleton(), nullptr, c.last, c.last_angles, c.now, right_planted, c.a);
  EXPECT_LE(hand_depth_in_thigh(human_skeleton(), c.a, c.last_angles, 1), std::max(-0.01f, hand_before));
}

}  // namespace
}  // namespace mc::anim
