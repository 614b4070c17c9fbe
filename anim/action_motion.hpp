// Actions layered over locomotion: kick, tackle, goalie catch and dive. An
// ActionMotion is planned once per action (kick_planner.hpp) in field space,
// then sampled at any time around its contact instant.
//
// Timing: tau is the time in seconds from the action's contact instant. A
// kick's contact lies half-way between two simulation cycles (the paper's
// intermediate state), so tau = 0 falls on a substep-1 frame.
#pragma once

#include <array>
#include <cstdint>

#include "anim/anim_events.hpp"
#include "anim/human_skeleton.hpp"

namespace mc::anim {

enum class MotionKind : std::uint8_t { Kick = 0, Tackle, Catch, Dive };

struct ActionMotion {
  MotionKind kind = MotionKind::Kick;
  Foot foot = Foot::Right;       // kicking foot; the leading leg of a tackle
  float ball_x = 0, ball_y = 0;  // field m: ball at contact
  float dir_x = 1, dir_y = 0;    // field unit vector: kick / tackle / dive direction
  float contact_x = 0, contact_y = 0, contact_h = 0;  // field: kicking ankle at contact (m)
  float ball_radius = 0.085f;    // m
  float foot_yaw = 0;            // field deg: kicking sole's heading at contact
  float support_x = 0, support_y = 0;  // field m: support foot planted through contact
  float lunge_x = 0, lunge_y = 0;  // field m: root offset at the contact frame (step-in), 0 at cycles
  float pelvis_height = 0.88f;   // m at contact
  // Kick: the backswing's share (0-1) of its full wind-up. A contact behind
  // the hips is reached back for, with little wind-up.
  float backswing = 1.0f;
  float side = 1;                // dive / catch side: +1 the body's right, -1 its left
  float start_s = -0.15f;        // tau when the motion begins (<= 0)
  float follow_s = 0.2f;         // tau when the follow-through ends (prolonged by merged kicks)
  float end_s = 0.35f;           // tau when locomotion has taken over again
  double contact_time_s = 0;     // stream time of the contact (s since frame 0)
  float last_contact_s = 0;      // tau of the last kick merged into this one (0: none merged)
  std::uint64_t last_kick_pos = 0;  // stream position of the last kick merged into this one
};

// What an action contributes to a frame.
struct ActionSample {
  float weight = 0;  // 0: locomotion only .. 1: the action alone
  // Kick: targets for both ankles in field space (height in m), replacing
  // locomotion's feet with `weight`; [0] right, [1] left.
  bool feet = false;
  float foot_x[2] = {0, 0}, foot_y[2] = {0, 0}, foot_h[2] = {0, 0};
  float foot_yaw[2] = {0, 0};    // field deg
  float foot_pitch[2] = {0, 0};  // deg, + toes up
  bool planted[2] = {false, false};
  // Kick: how much each foot follows the kick rather than locomotion (the
  // support foot is handed over only shortly before it plants).
  float foot_weight[2] = {0, 0};
  float root_dx = 0, root_dy = 0;  // field m
  // Kick: this is the contact frame; the kicking foot's box must touch the
  // ball, whose centre is (ball_x, ball_y, ball_h) (field m) and radius ball_r.
  bool contact = false;
  int kick_foot = 0;  // Kick: the kicking foot on every frame of the kick, [0] right, [1] left
  float to_contact_s = 0;  // Kick: time still to go to the contact (s; negative after it)
  // Kick: where the kicking ankle will be at the contact (field m, height m).
  float contact_ankle_x = 0, contact_ankle_y = 0, contact_ankle_h = 0;
  bool support_lands = false;  // Kick: the support foot plants on its spot this frame
  float ball_x = 0, ball_y = 0, ball_h = 0.085f, ball_r = 0.085f;
  float pelvis_height = 0.9f;
  // Angles blended over locomotion's with `weight`: all dofs (tackle, dive)
  // or only the pelvis, torso and arms (kick, catch: the legs keep their
  // footsteps).
  bool whole_body = false;
  std::array<float, dof::kCount> angles{};
};

// Samples `m` at `tau` for a player whose body heading is `heading` (field
// deg) and whose 2D root is at (root_x, root_y) (field m; the kicking foot
// comes down beside it). Returns weight 0 outside [start_s, end_s].
ActionSample sample_action(const ActionMotion& m, float tau, float heading, float root_x, float root_y);

}  // namespace mc::anim
