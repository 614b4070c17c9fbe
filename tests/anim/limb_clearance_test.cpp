// separate_legs: with both feet up, the leg that has crossed towards the
// other side is the one turned out; with a foot planted, only the leg in the
// air turns.
#include "anim/limb_clearance.hpp"

#include <gtest/gtest.h>

#include <array>

#include "anim/human_skeleton.hpp"

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

}  // namespace
}  // namespace mc::anim
