// keep_legs_apart_drawn: legs that are apart at both frames but pass
// through each other as the clients draw the frame between them
// (LegBlend, proto/SPEC.md 4.7) are turned apart at the frame (at the hip,
// or a swing that crosses low lifted with its knee); the planted leg
// stays, the joints keep within their speed limits, and frames whose blend
// is clear are left alone.
#include "anim/drawn_leg_clearance.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <span>

#include "anim/human_skeleton.hpp"
#include "anim/leg_blend.hpp"
#include "anim/limb_clearance.hpp"
#include "anim/player_animation.hpp"

namespace mc::anim {
namespace {

constexpr float kPelvisH = 1.05f;  // feet off the grass: a flight phase

// A stride with both legs swung in towards the midline (each hip adducted
// `in` deg): the right leg from `flex` deg forward to as far back, the left
// the other way. Half-way both hang side by side, knees together.
std::array<float, dof::kCount> stride(float flex, float in) {
  std::array<float, dof::kCount> a{};
  a[dof::kRHip] = flex;
  a[dof::kRHip + 1] = in;  // the right leg adducts towards +X
  a[dof::kLHip] = -flex;
  a[dof::kLHip + 1] = -in;  // the left towards -X
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
  std::array<float, dof::kCount> last_angles = stride(12.0f, 12.0f);
  PlayerPose last = pose(last_angles);
  std::array<float, dof::kCount> a = stride(-12.0f, 12.0f);
  DrawnRoot now{10.0f, -5.0f, kPelvisH, 30.0f};
  float drawn() const { return drawn_leg_clearance(legs, last, now, a); }
};

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
  // Only the left hip turned; the planted right leg and the rest stayed.
  for (int d = 0; d < dof::kCount; ++d) {
    if (d >= dof::kLHip && d < dof::kLHip + 3) continue;
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

TEST(KeepLegsApartDrawn, ASwingThatCrossesLowLiftsItsFootWithTheKnee) {
  // The left leg straight under its hip on the grass; the right swings from
  // 28 deg back to 28 deg forward, adducted 16 deg (a step that crosses in
  // front of the planted foot), its knee straightening from 20 deg. Both
  // frames keep the legs apart; half-way through, the swinging foot passes
  // through the planted one. No turn of the hip clears it as well as
  // bending the knee a little more at the frame, which lifts the foot as
  // it passes.
  LegBlend legs{human_skeleton()};
  std::array<float, dof::kCount> last_angles{}, a{};
  last_angles[dof::kRHip] = -28.0f;
  last_angles[dof::kRHip + 1] = 16.0f;
  last_angles[dof::kRKnee] = -20.0f;
  a[dof::kRHip] = 28.0f;
  a[dof::kRHip + 1] = 16.0f;
  auto at = [](const std::array<float, dof::kCount>& q) {
    PlayerPose p = pose(q);
    p.z = 1.0f;
    return p;
  };
  const PlayerPose last = at(last_angles);
  const DrawnRoot now{10.0f, -5.0f, 1.0f, 30.0f};
  ASSERT_GT(legs.clearance(last), kDrawnApartM);
  ASSERT_GT(legs.clearance(at(a)), kDrawnApartM);
  ASSERT_LT(drawn_leg_clearance(legs, last, now, a), 0.0f);
  const auto before = a;
  const bool left_planted[2] = {false, true};
  EXPECT_TRUE(keep_legs_apart_drawn(legs, human_skeleton(), nullptr, last, last_angles, now, left_planted, a));
  EXPECT_GE(drawn_leg_clearance(legs, last, now, a), 0.0f);
  // The right knee bent further; nothing else moved.
  EXPECT_LT(a[dof::kRKnee], before[dof::kRKnee]);
  for (int d = 0; d < dof::kCount; ++d) {
    if (d == dof::kRKnee) continue;
    EXPECT_EQ(a[static_cast<std::size_t>(d)], before[static_cast<std::size_t>(d)]) << d;
  }
  // Within the joint speed limit since the frame before.
  EXPECT_LE(std::fabs(a[dof::kRKnee] - last_angles[dof::kRKnee]), kMaxLegStepDeg);
}

TEST(KeepLegsApartDrawn, TheKneeStaysWithinItsSpeedLimit) {
  // The same crossing swing, its knee bent 50 deg since the frame before
  // (the joint speed limit) and the frame's own feet too close: bending it
  // further would clear the blend (to -82 deg), but faster than a knee may
  // turn.
  LegBlend legs{human_skeleton()};
  std::array<float, dof::kCount> last_angles{}, a{};
  last_angles[dof::kRHip] = -28.0f;
  last_angles[dof::kRHip + 1] = 12.0f;
  a[dof::kRHip] = 28.0f;
  a[dof::kRHip + 1] = 12.0f;
  a[dof::kRKnee] = -kMaxLegStepDeg;
  PlayerPose last = pose(last_angles);
  last.z = 1.0f;
  const DrawnRoot now{10.0f, -5.0f, 1.0f, 30.0f};
  ASSERT_LT(drawn_leg_clearance(legs, last, now, a), 0.0f);
  const bool left_planted[2] = {false, true};
  keep_legs_apart_drawn(legs, human_skeleton(), nullptr, last, last_angles, now, left_planted, a);
  EXPECT_LE(std::fabs(a[dof::kRKnee] - last_angles[dof::kRKnee]), kMaxLegStepDeg);
}

TEST(KeepLegsApartDrawn, TheTurnStaysWithinTheHipsSpeedLimit) {
  // The right hip already turned 50 deg inwards since the frame before (as
  // the joint speed limit measures it): turning it out would take it past
  // the limit, so it is not turned out, however close the blend.
  Case c;
  c.last_angles[dof::kRHip + 1] = c.a[dof::kRHip + 1] + 50.0f;
  ASSERT_LT(hip_turning_too_fast(c.last_angles, c.a, kMaxLegStepDeg + kSeparateAgainDeg), 0);
  ASSERT_LT(c.drawn(), 0.0f);
  const bool left_planted[2] = {false, true};
  keep_legs_apart_drawn(c.legs, human_skeleton(), nullptr, c.last, c.last_angles, c.now, left_planted, c.a);
  EXPECT_LT(hip_turning_too_fast(c.last_angles, c.a, kMaxLegStepDeg + kSeparateAgainDeg), 0);
}

}  // namespace
}  // namespace mc::anim
