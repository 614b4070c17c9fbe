// separate_legs: with both feet up, the leg that has crossed towards the
// other side is the one turned out; with a foot planted, only the leg in the
// air turns. separate_legs_again: as far as the hip's speed limit lets it.
// keep_hands_off_thighs: a hand out of its thigh, at the frame and in the
// clients' blend from the frame before.
#include "anim/limb_clearance.hpp"

#include <gtest/gtest.h>

#include <array>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

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

// keep_hands_off_thighs. How deep (m) side `side`'s hand's box (0 right, 1
// left) is in its own side's thigh's at the pose `a`: the deepest of its
// corners, edge midpoints and centre (> 0 inside).
float hand_depth(std::span<const float> a, int side) {
  const SkeletonDef& skel = human_skeleton();
  std::array<glm::mat4, kHumanJointCount> m;
  LocalToModelJob fk{&skel, a, glm::vec3(0.0f, 1.0f, 0.0f), m};
  EXPECT_TRUE(fk.Run());
  const int hand = side == 0 ? kRHand : kLHand, thigh = side == 0 ? kRThigh : kLThigh;
  const Segment& hs = skel.joints[static_cast<std::size_t>(hand)].segment;
  const Segment& ts = skel.joints[static_cast<std::size_t>(thigh)].segment;
  const glm::mat4 to_thigh = glm::inverse(m[static_cast<std::size_t>(thigh)]) * m[static_cast<std::size_t>(hand)];
  float depth = -1;
  for (float sx : {-0.5f, 0.0f, 0.5f})
    for (float sy : {-0.5f, 0.0f, 0.5f})
      for (float sz : {-0.5f, 0.0f, 0.5f}) {
        const glm::vec3 p(hs.center[0] + sx * hs.size[0], hs.center[1] + sy * hs.size[1], hs.center[2] + sz * hs.size[2]);
        depth = std::max(depth, -box_distance(ts, glm::vec3(to_thigh * glm::vec4(p, 1.0f)), nullptr));
      }
  return depth;
}
float left_hand_depth(std::span<const float> a) { return hand_depth(a, 1); }

std::array<float, dof::kCount> blend(const std::array<float, dof::kCount>& a, const std::array<float, dof::kCount>& b,
                                     float t) {
  std::array<float, dof::kCount> o{};
  for (std::size_t d = 0; d < o.size(); ++d) o[d] = a[d] + (b[d] - a[d]) * t;
  return o;
}

// Two frames of game 2 (seq 1920-1921, right 3, sprinting at 8.5 m/s): the
// left thigh, raised and turned out 45 deg, comes in as the left arm
// swings back. Each frame has the hand clear of the thigh, and the
// clients' blend at 60 Hz drew it 3.2 cm inside.
constexpr std::array<float, dof::kCount> kSprintLast{
    2.37f,   -3.97f, 1.03f,  -4.78f,  -6.09f, -0.69f, 35.15f, 5.08f,  0.00f,  52.72f,   3.05f,  0.00f,
    -32.28f, -20.0f, 0.00f,  86.99f,  0.00f,  0.00f,  -8.35f, 26.82f, 0.00f,  86.99f,   0.00f,  0.00f,
    -21.19f, 9.40f,  -1.44f, -19.37f, 20.19f, -9.79f, 97.56f, 44.54f, -1.91f, -111.03f, 12.30f, 6.07f};
constexpr std::array<float, dof::kCount> kSprintNow{
    -2.99f,  -4.06f, -1.03f, 7.48f,   -6.09f, 1.03f,  10.48f, 5.08f,  0.00f,  15.72f,  3.05f,  0.00f,
    -1.61f,  -20.0f, 0.00f,  86.99f,  0.00f,  0.00f,  -39.02f, 20.00f, 0.00f, 86.99f,  0.00f,  0.00f,
    -34.77f, 13.80f, 2.99f,  -33.56f, 33.00f, -14.36f, 85.96f, 12.13f, 2.99f, -81.94f, -0.29f, 2.33f};

TEST(KeepHandsOffThighs, AHandInTheThighIsLiftedOut) {
  std::array<float, dof::kCount> a{};
  a[dof::kLHip + 1] = 20;  // the left thigh splayed out, the arm hanging at the side
  ASSERT_GT(left_hand_depth(a), 0.05f);
  keep_hands_off_thighs(human_skeleton(), a);
  EXPECT_LE(left_hand_depth(a), -0.055f);
  EXPECT_GT(a[dof::kLShoulder + 1], 0.0f);  // lifted away from the body (left: +X)
}

TEST(KeepHandsOffThighs, TheClientsBlendFromTheLastFrameIsKeptClear) {
  // The case as it was: both frames clear, a third of the way inside.
  ASSERT_LT(left_hand_depth(kSprintLast), -0.04f);
  ASSERT_LT(left_hand_depth(kSprintNow), -0.04f);
  ASSERT_GT(left_hand_depth(blend(kSprintLast, kSprintNow, 1.0f / 3.0f)), 0.02f);
  // Without the last frame the blend is not seen.
  auto alone = kSprintNow;
  keep_hands_off_thighs(human_skeleton(), alone);
  EXPECT_GT(left_hand_depth(blend(kSprintLast, alone, 1.0f / 3.0f)), 0.02f);
  // With it, the arm turns out at this frame far enough for the blend.
  auto a = kSprintNow;
  keep_hands_off_thighs(human_skeleton(), a, kSprintLast);
  // (It aims at 1 cm clear; the arm's first-order step undershoots here, 1 mm.)
  for (float t : {1.0f / 3.0f, 0.5f, 2.0f / 3.0f}) EXPECT_LE(left_hand_depth(blend(kSprintLast, a, t)), 0.0f) << t;
  EXPECT_GT(a[dof::kLShoulder + 1], kSprintNow[dof::kLShoulder + 1]);
  EXPECT_LE(a[dof::kLShoulder + 1] - kSprintLast[dof::kLShoulder + 1], 45.0f);  // the arms' bound a frame
  // The right arm, clear throughout, is left alone.
  EXPECT_EQ(a[dof::kRShoulder + 1], kSprintNow[dof::kRShoulder + 1]);
}

// Two frames of game 2 (seq 4747-4748, left 8): the right thigh, raised
// 64 deg and splayed, turns 9.5 deg with the arm; each frame has the
// right hand 6 cm out, and half-way between it is 3.8 cm in.
constexpr std::array<float, dof::kCount> kSplayLast{
    -3.89f, -1.30f, -1.40f, 9.11f, -1.95f, 1.40f, -51.94f, 1.62f, 0.00f, -77.92f, 0.97f, 0.00f,
    9.89f, -14.60f, 0.00f, 29.14f, 0.00f, 0.00f, -22.86f, 14.60f, 0.00f, 29.14f, 0.00f, 0.00f,
    55.75f, -44.07f, 29.65f, -11.47f, 0.90f, 28.00f, 11.28f, 16.77f, 33.89f, -44.86f, 27.99f, -6.90f};
constexpr std::array<float, dof::kCount> kSplayNow{
    -2.28f, -0.97f, -1.31f, 5.24f, -1.45f, 1.31f, -37.24f, 1.21f, 0.00f, -55.86f, 0.72f, 0.00f,
    3.52f, -13.80f, 0.00f, 20.57f, 0.00f, 0.00f, -13.17f, 13.80f, 0.00f, 20.57f, 0.00f, 0.00f,
    64.54f, -34.53f, 22.93f, -11.47f, -17.69f, 28.00f, -10.04f, 18.35f, 34.76f, -24.73f, 23.67f, -20.18f};

TEST(KeepHandsOffThighs, ASmallTurnIsCheckedInTheBlendToo) {
  ASSERT_GT(hand_depth(blend(kSplayLast, kSplayNow, 0.5f), 0), 0.03f);
  auto a = kSplayNow;
  keep_hands_off_thighs(human_skeleton(), a, kSplayLast);
  for (float t : {1.0f / 3.0f, 0.5f, 2.0f / 3.0f}) EXPECT_LE(hand_depth(blend(kSplayLast, a, t), 0), 0.0f) << t;
  EXPECT_LT(a[dof::kRShoulder + 1], kSplayNow[dof::kRShoulder + 1]);  // lifted away (right: -X)
}

// Two frames of game 1 (seq 3640-3641, right 1): the right hand, 4 cm from
// its thigh in the frame before, is 11 cm out at this one, and the thigh
// swinging back passes through it between them.
constexpr std::array<float, dof::kCount> kPassLast{
    2.47f, -5.21f, 0.58f, -5.67f, -4.81f, -0.58f, 15.81f, 1.40f, 0.00f, 23.71f, 0.84f, 0.00f,
    -13.12f, -9.94f, 0.00f, 25.07f, 0.00f, 0.00f, 13.56f, 5.53f, 0.00f, 25.07f, 0.00f, 0.00f,
    28.14f, -12.25f, -26.47f, -49.33f, 23.73f, -0.43f, 31.17f, 5.91f, 3.49f, -68.00f, 15.28f, -2.90f};
constexpr std::array<float, dof::kCount> kPassNow{
    0.25f, -11.21f, 0.11f, -0.58f, -9.41f, -0.11f, 40.48f, 1.67f, 0.00f, 60.71f, 1.00f, 0.00f,
    7.41f, -4.01f, 0.00f, 34.13f, 0.00f, 0.00f, 27.02f, 4.01f, 0.00f, 34.13f, 0.00f, 0.00f,
    11.48f, -32.82f, -29.84f, -48.62f, 32.70f, 27.94f, 28.79f, -19.48f, -5.88f, -82.31f, 33.00f, 13.83f};

TEST(KeepHandsOffThighs, AHandNearItsThighInTheFrameBeforeIsCheckedInTheBlend) {
  ASSERT_LT(hand_depth(kPassNow, 0), -0.09f);
  ASSERT_GT(hand_depth(kPassLast, 0), -0.08f);
  ASSERT_GT(hand_depth(blend(kPassLast, kPassNow, 0.5f), 0), -0.005f);
  // Not near in the frame before: the hand, far at this one, is let be.
  bool near[2] = {false, false};
  auto a = kPassNow;
  keep_hands_off_thighs(human_skeleton(), a, kPassLast, near);
  EXPECT_EQ(a, kPassNow);
  EXPECT_FALSE(near[0]);  // and it is not near now
  // Near in the frame before: the blend is checked, and the arm turns out.
  near[0] = true;
  keep_hands_off_thighs(human_skeleton(), a, kPassLast, near);
  EXPECT_LT(a[dof::kRShoulder + 1], kPassNow[dof::kRShoulder + 1]);
  for (float t : {1.0f / 3.0f, 0.5f, 2.0f / 3.0f}) EXPECT_LE(hand_depth(blend(kPassLast, a, t), 0), -0.005f) << t;
  EXPECT_FALSE(near[0]);
}

}  // namespace
}  // namespace mc::anim
