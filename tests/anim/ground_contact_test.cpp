#include "anim/ground_contact.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "anim/action_motion.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/player_animation.hpp"

namespace mc::anim {
namespace {

std::vector<glm::mat4> pose_models(const std::array<float, kMaxDof>& a, float pelvis_h) {
  std::vector<glm::mat4> m(human_skeleton().joints.size());
  LocalToModelJob fk{&human_skeleton(), a, glm::vec3(0, pelvis_h, 0), m};
  EXPECT_TRUE(fk.Run());
  return m;
}

// Standing straight, the soles are on the grass: the lowest point is 0.
TEST(GroundContact, RestPoseStandsOnTheGrass) {
  const std::array<float, kMaxDof> a{};
  const auto m = pose_models(a, dims::kStandPelvis);
  EXPECT_NEAR(lowest_point_ms(human_skeleton(), m), 0.0f, 1e-5f);
  const auto low = pose_models(a, dims::kStandPelvis - 0.1f);
  EXPECT_NEAR(lowest_point_ms(human_skeleton(), low), -0.1f, 1e-5f);
}

// A pitched sole needs the ankle higher: by the toe's drop when toes down,
// by the heel's when toes up; level, the ankle height itself.
TEST(GroundContact, MinAnkleHeightFollowsThePitch) {
  EXPECT_NEAR(min_ankle_height(0), dims::kAnkleHeight, 1e-6f);
  const float r = 20.0f * 3.14159265f / 180.0f;
  EXPECT_NEAR(min_ankle_height(-20), dims::kFootFront * std::sin(r) + dims::kAnkleHeight * std::cos(r), 1e-5f);
  EXPECT_NEAR(min_ankle_height(20), dims::kFootBack * std::sin(r) + dims::kAnkleHeight * std::cos(r), 1e-5f);
}

// A foot pitched toes-down into the grass turns level by the smallest
// angle, and not further than the bounds it is given.
TEST(GroundContact, LevelFootTurnsTheAnkleAsLittleAsPossible) {
  std::array<float, kMaxDof> a{};
  a[dof::kRAnkle] = -30;  // toes down
  auto m = pose_models(a, dims::kStandPelvis);
  ASSERT_LT(segment_lowest_ms(human_skeleton().joints[kRFoot].segment, m[kRFoot]), -0.05f);
  const float after = level_foot(human_skeleton(), m, a, kRFoot, dof::kRAnkle);
  EXPECT_GE(after, -1e-4f);
  EXPECT_NEAR(a[dof::kRAnkle], 0.0f, 1.01f);  // level is the nearest pitch that clears
  // The model transform written back is the one FK gives for the new angle.
  const auto again = pose_models(a, dims::kStandPelvis);
  EXPECT_NEAR(after, segment_lowest_ms(human_skeleton().joints[kRFoot].segment, again[kRFoot]), 1e-5f);

  a[dof::kRAnkle] = -30;
  m = pose_models(a, dims::kStandPelvis);
  const float bounded = level_foot(human_skeleton(), m, a, kRFoot, dof::kRAnkle, -44, -16);
  EXPECT_FLOAT_EQ(a[dof::kRAnkle], -16.0f);  // as far as allowed, still under
  EXPECT_LT(bounded, 0.0f);
}

// A foot in the air skimming the grass toes down (0.5 cm up, as the joint
// speed limit can leave a swing) turns towards level until its sole is at
// the clearance asked for, by as little as that takes.
TEST(GroundContact, LevelFootLiftsASkimmingSoleToItsClearance) {
  std::array<float, kMaxDof> a{};
  a[dof::kRAnkle] = -30;  // toes down
  a[dof::kRHip] = 10;     // the leg a little forward: the foot in the air
  a[dof::kRKnee] = -60;
  auto m = pose_models(a, dims::kStandPelvis);
  const float start = segment_lowest_ms(human_skeleton().joints[kRFoot].segment, m[kRFoot]);
  // Lowered so that the toes are 0.5 cm up.
  m = pose_models(a, dims::kStandPelvis - start + 0.005f);
  ASSERT_NEAR(segment_lowest_ms(human_skeleton().joints[kRFoot].segment, m[kRFoot]), 0.005f, 1e-4f);
  EXPECT_NEAR(level_foot(human_skeleton(), m, a, kRFoot, dof::kRAnkle), 0.005f, 1e-4f)
      << "above the grass: no clearance asked, nothing to do";
  EXPECT_FLOAT_EQ(a[dof::kRAnkle], -30.0f);
  const float after = level_foot(human_skeleton(), m, a, kRFoot, dof::kRAnkle, -INFINITY, INFINITY, 0.05f);
  EXPECT_GE(after, 0.05f - 1e-4f);
  EXPECT_LT(after, 0.05f + 0.002f) << "no further than the clearance";
  EXPECT_GT(a[dof::kRAnkle], -30.0f);  // turned toes up
}

// Tackles and dives are given as joint angles, a catch lowers the pelvis
// over the legs' own footsteps; whatever their weight, the animated body
// rests on the grass and is not buried in it.
TEST(GroundContact, WholeBodyActionsRestOnTheGrass) {
  for (MotionKind kind : {MotionKind::Tackle, MotionKind::Catch, MotionKind::Dive}) {
    ActionMotion motion;
    motion.kind = kind;
    motion.start_s = -0.15f;
    motion.end_s = 0.9f;
    float lowest_seen = 1;
    PlayerAnim ctx;
    for (float tau = -0.15f; tau <= 0.9f; tau += 0.05f) {
      const ActionSample layer = sample_action(motion, tau, 0, 0, 0);
      PlayerFrameInput in;
      in.action = Action::Tackle;
      in.layer = &layer;
      in.reset = tau < -0.1f;
      PlayerPose out;
      animate_player(ctx, in, FootstepParams{}, human_skeleton(), out);
      std::array<float, kMaxDof> a{};
      for (int d = 0; d < dof::kCount; ++d) a[static_cast<std::size_t>(d)] = out.angles[static_cast<std::size_t>(d)];
      const float low = lowest_point_ms(human_skeleton(), pose_models(a, out.z));
      EXPECT_GE(low, -1e-3f) << "kind " << static_cast<int>(kind) << " tau " << tau;
      lowest_seen = std::min(lowest_seen, low);
    }
    EXPECT_LT(lowest_seen, 0.05f) << "kind " << static_cast<int>(kind);  // and it does reach the grass
  }
}

// What a client does to every pose it draws (proto/SPEC.md 4.7): a pose
// whose soles are under the grass (as a blend of two frames can leave them)
// is raised by what lies deeper than 1 cm; a body on the grass is left where
// it is, and so is a player off the pitch.
TEST(GroundContact, ADrawnPoseRestsOnTheGrass) {
  const SkeletonDef& skel = human_skeleton();
  PoseFrame f;
  for (PlayerPose& p : f.players) p.side = Side::Neutral;
  f.players[0].side = Side::Left;
  f.players[0].unum = 1;
  f.players[0].z = dims::kStandPelvis;  // standing straight: soles on the grass
  PoseFrame rested = f;
  rest_on_grass(skel, rested);
  EXPECT_FLOAT_EQ(rested.players[0].z, f.players[0].z);
  f.players[0].z -= 0.06f;  // sunk 6 cm
  f.players[1] = f.players[0];
  f.players[1].side = Side::Neutral;
  rest_on_grass(skel, f);
  EXPECT_NEAR(f.players[0].z, dims::kStandPelvis - kGrassToleranceM, 0.003f);
  EXPECT_FLOAT_EQ(f.players[1].z, dims::kStandPelvis - 0.06f) << "off the pitch: not touched";
  // A knee bent under a pelvis left at standing height (the blend's dip
  // the other way round) is not lowered: the grass only ever pushes up.
  PlayerPose bent = rested.players[0];
  bent.angles[static_cast<std::size_t>(dof::kRKnee)] = -60;
  EXPECT_EQ(rest_on_grass(skel, bent), 0.0f);
}

// A player running along +x at `speed` through a catch (at frame 20 of
// 40): what a viewer sees of the feet and the body while the catch plays.
struct CatchOnTheRun {
  float worst_grounded_move = 0;  // m a foot on the grass moved in a frame
  int grounded_pairs = 0;         // frame pairs with a foot on the grass in both
  float lowest_pelvis = 1, highest_arm = -90;
};

CatchOnTheRun run_through_a_catch(float speed) {
  ActionMotion motion;
  motion.kind = MotionKind::Catch;
  motion.start_s = -0.15f;
  motion.end_s = 0.5f;
  constexpr float kDt = 0.05f;
  CatchOnTheRun r;
  PlayerAnim ctx;
  float last_ankle[2][2] = {};
  bool last_grounded[2] = {false, false};
  for (int f = 0; f < 40; ++f) {
    const ActionSample layer = sample_action(motion, static_cast<float>(f - 20) * kDt, 0, 0, 0);
    PlayerFrameInput in;
    in.x = speed * kDt * static_cast<float>(f);
    in.action = Action::Run;
    in.dt = kDt;
    in.move_dx = 1;
    in.reset = f == 0;
    in.layer = layer.weight > 0 ? &layer : nullptr;
    for (int k = 0; k < kPathAhead; ++k) in.ahead_x[k] = in.x + speed * kDt * static_cast<float>(k + 1);
    in.ahead_n = kPathAhead;
    PlayerPose out;
    animate_player(ctx, in, FootstepParams{}, human_skeleton(), out);
    std::array<float, kMaxDof> a{};
    for (int d = 0; d < dof::kCount; ++d) a[static_cast<std::size_t>(d)] = out.angles[static_cast<std::size_t>(d)];
    const auto m = pose_models(a, out.z);
    const float c = std::cos(out.heading * kDeg), s = std::sin(out.heading * kDeg);
    for (int i = 0; i < 2; ++i) {
      const glm::vec3 ankle(m[static_cast<std::size_t>(i == 0 ? kRFoot : kLFoot)][3]);
      const float fx = out.x + ankle.x * c - ankle.z * s, fy = out.y + ankle.x * s + ankle.z * c;
      // A foot on the grass as a viewer sees it: its ankle at most 1 cm
      // above its standing height.
      const bool grounded = ankle.y < dims::kAnkleHeight + 0.01f;
      if (layer.weight > 0 && grounded && last_grounded[i]) {
        ++r.grounded_pairs;
        r.worst_grounded_move = std::max(r.worst_grounded_move, std::hypot(fx - last_ankle[i][0], fy - last_ankle[i][1]));
      }
      last_ankle[i][0] = fx;
      last_ankle[i][1] = fy;
      last_grounded[i] = grounded;
    }
    if (layer.weight > 0.9f) {
      r.lowest_pelvis = std::min(r.lowest_pelvis, out.z);
      r.highest_arm = std::max(r.highest_arm, out.angles[dof::kRShoulder]);
    }
  }
  return r;
}

// A goalkeeper who catches on the run keeps running: the catch is the arms'
// and the trunk's, and the feet stay on their footsteps (a foot on the
// grass does not move) while the pelvis lowers into the crouch. Given as
// a whole-body crouch, both feet glided with the body (game 1 seq
// 1486-1491, a goalkeeper at 6-10 m/s): 8-27 cm a frame here.
TEST(GroundContact, ACatchOnTheRunKeepsTheFeetOnTheGrassStill) {
  for (float speed : {3.0f, 5.5f}) {
    SCOPED_TRACE(testing::Message() << speed << " m/s");
    const CatchOnTheRun r = run_through_a_catch(speed);
    EXPECT_GE(r.grounded_pairs, 2);  // a foot did stand on the grass in the catch
    EXPECT_LT(r.worst_grounded_move, 0.03f);
    EXPECT_LT(r.lowest_pelvis, 0.88f);  // a crouch
    EXPECT_GT(r.highest_arm, 60.0f);    // the arms take the ball in
  }
}

}  // namespace
}  // namespace mc::anim