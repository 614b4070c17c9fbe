// separate_legs: with both feet up, the leg that has crossed towards the
// other side is the one turned out; with a foot planted, only the leg in the
// air turns. separate_legs_again: as far as the hip's speed limit lets it.
#include "anim/limb_clearance.hpp"

#include <gtest/gtest.h>

#include <array>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/player_animation.hpp"

namespace mc::anim {
namespace {

constexpr float kPelvisH = 0.93f;

// The right thigh abducted 2 deg, the left one adducted 20 deg across the
// body's midline (a crossover step): thighs and shins too close.
std::array<float, dof::kCount> crossover() {
  std::array<float, dof::kCount> a{};
  a[dof::kRHip + 1] = -2;   // right abducts towards -X
  a[dof::kLHip + 1] = -20;  // left adducts towards -X, across
  return a;
}

TEST(SeparateLegs, WithBothFeetUpTheLegFurtherAcrossTurnsOut) {
  auto a = crossover();
  const bool in_air[2] = {false, false};
  EXPECT_FALSE(separate_legs(a, kPelvisH, in_air));  // apart now
  EXPECT_FLOAT_EQ(a[dof::kRHip + 1], -2.0f);          // the right leg was left as it was
  EXPECT_GT(a[dof::kLHip + 1], -20.0f);                // the left one turned back out
}

TEST(SeparateLegs, WithAFootPlantedOnlyTheLegInTheAirTurns) {
  // The mirror image: the right leg across, and planted; the left in the air.
  std::array<float, dof::kCount> a{};
  a[dof::kRHip + 1] = 20;  // right adducted across (towards +X)
  a[dof::kLHip + 1] = 2;   // left abducted
  const bool right_planted[2] = {true, false};
  separate_legs(a, kPelvisH, right_planted);
  EXPECT_FLOAT_EQ(a[dof::kRHip + 1], 20.0f);  // the planted leg, further across, stays
  EXPECT_GT(a[dof::kLHip + 1], 2.0f);         // the leg in the air turned out
}

TEST(SeparateLegs, LegsApartAreLeftAlone) {
  std::array<float, dof::kCount> a{};
  a[dof::kRHip + 1] = -5;
  a[dof::kLHip + 1] = 5;
  const auto before = a;
  const bool in_air[2] = {false, false};
  EXPECT_FALSE(separate_legs(a, kPelvisH, in_air));
  EXPECT_EQ(a, before);
}

// separate_legs_again from a last frame that leaves the hip little room: a
// turn-out too fast in full is taken as far as the limits let it, not
// refused (game 2 seq 11560 kept its shins 3.8 cm inside each other).
TEST(SeparateLegsAgain, ATurnOutTooFastInFullTurnsAsFarAsTheLimitLets) {
  auto a = crossover();
  std::array<float, dof::kCount> last = a;
  // The left hip's twist turned 57 deg since the last frame, near the
  // legs' 58 deg: the whole turn-out would take it past.
  last[dof::kLHip + 2] = -45;
  a[dof::kLHip + 2] = 12;
  const bool right_planted[2] = {true, false};
  const BodyFrame body(0, 0, 0);
  // What the full turn-out is: from a last frame equal to this one.
  auto free = a;
  separate_legs_again(human_skeleton(), body, kPelvisH, a, nullptr, right_planted, free);
  ASSERT_GT(free[dof::kLHip + 1], -20.0f + 1.0f) << "the legs were too close";
  const float full_turn = rotation_between("zxy", &last[dof::kLHip], &free[dof::kLHip]);
  ASSERT_GT(full_turn, kMaxLegStepDeg + 8.0f) << "the full turn-out must be too fast for this test";

  separate_legs_again(human_skeleton(), body, kPelvisH, last, nullptr, right_planted, a);
  EXPECT_GT(a[dof::kLHip + 1], -20.0f + 0.5f) << "turned out part of the way";
  EXPECT_LT(a[dof::kLHip + 1], free[dof::kLHip + 1]) << "not the whole way";
  EXPECT_LE(rotation_between("zxy", &last[dof::kLHip], &a[dof::kLHip]), kMaxLegStepDeg + 8.0f + 1e-3f);
  EXPECT_FLOAT_EQ(a[dof::kRHip + 1], -2.0f);  // the planted leg stays
}

}  // namespace
}  // namespace mc::anim
