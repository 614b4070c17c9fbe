// keep_legs_apart_drawn: legs that are apart at both frames but pass
// through each other as the clients draw the frame between them
// (LegBlend, proto/SPEC.md 4.7) are turned apart at the frame; the planted
// leg stays, the hip keeps within its speed limit, and frames whose blend
// is clear are left alone.
#include "anim/drawn_leg_clearance.hpp"

#include <gtest/gtest.h>

#include <array>
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
