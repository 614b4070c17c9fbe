#include "anim/foot_passing.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace mc::anim {
namespace {

// A body at the origin heading +x (field +y is its right, +Z); the right
// foot planted under its hip, the left one swinging.
const BodyFrame kBody(0, 0, 0);

PassingStep left_past_right() {
  PassingStep p;
  p.side = -1;
  p.other_x = 0.0f;
  p.other_y = 0.11f;
  p.min_gap = 0.17f;
  p.past_hip = 0.55f;
  return p;
}

TEST(FootPassing, AFootClearOfTheOtherIsLeftAlone) {
  PassingStep p = left_past_right();
  p.from_x = -0.3f;
  p.from_y = -0.11f;
  float x = 0.1f, y = -0.11f;
  pass_other_foot(kBody, p, x, y);
  EXPECT_EQ(x, 0.1f);
  EXPECT_EQ(y, -0.11f);
}

TEST(FootPassing, AFootBesideTheOtherGoesToItsOwnSide) {
  PassingStep p = left_past_right();
  p.from_x = -0.3f;
  p.from_y = 0.0f;
  float x = 0.05f, y = 0.02f;  // 9 cm left of the other: too close
  pass_other_foot(kBody, p, x, y);
  EXPECT_NEAR(x, 0.05f, 1e-6f);
  EXPECT_NEAR(y, 0.11f - 0.17f, 1e-6f);
}

// Crossed 0.4 m behind and to the right of the other foot (a fast turn),
// it uncrosses a pass length behind, not beside it.
TEST(FootPassing, ACrossedFootUncrossesAPassLengthOff) {
  PassingStep p = left_past_right();
  p.from_x = -0.4f;
  p.from_y = 0.37f;
  float x = -0.1f, y = 0.3f;
  pass_other_foot(kBody, p, x, y);
  EXPECT_NEAR(x, -kPassLength, 1e-6f);
  EXPECT_NEAR(y, 0.11f - 0.17f, 1e-6f);
}

// Its way crosses where the other foot stood as the frame began (that one
// has lifted and moved right since): it ends on its own side of both.
TEST(FootPassing, ItsWayPassesWhereTheOtherStood) {
  PassingStep p = left_past_right();
  p.other_y = 0.5f;  // the other foot now, lifted and gone right
  p.other_x = 0.3f;
  p.other_stood = true;
  p.stood_x = 0.0f;
  p.stood_y = 0.11f;
  p.from_x = -0.05f;
  p.from_y = -0.08f;
  float x = 0.35f, y = 0.2f;  // its swing alone ends right of where the other stood
  pass_other_foot(kBody, p, x, y);
  EXPECT_LE(y, 0.11f - 0.17f + 1e-6f);
  // Without the other foot's place at the frame's start, the end alone is
  // on the left of where that foot is now, and is not moved.
  p.other_stood = false;
  float x2 = 0.35f, y2 = 0.2f;
  pass_other_foot(kBody, p, x2, y2);
  EXPECT_EQ(y2, 0.2f);
}

TEST(FootPassing, APushStaysWithinTheSwingsBoundPastTheHip) {
  PassingStep p = left_past_right();
  p.from_x = -0.2f;
  p.from_y = 0.5f;  // far right of the other foot, crossed
  p.root_dx = 0.1f;
  p.past_hip = 0.45f;
  float x = 0.0f, y = 0.2f;
  pass_other_foot(kBody, p, x, y);
  EXPECT_LE(std::hypot(x - p.from_x - p.root_dx, y - p.from_y), 0.45f + 1e-5f);
  EXPECT_LT(y, 0.2f);  // but it went towards its own side
}

}  // namespace
}  // namespace mc::anim
