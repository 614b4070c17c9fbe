// Kicks (and the other actions) from 2D data: detection from the state bits
// and kick counters, the kick direction from the ball's motion, the choice of
// foot so that the legs never cross, the step-in when the foot cannot reach
// the ball, and the merging of kicks in consecutive cycles into one kick with
// a prolonged follow-through (Virtual RoboCup, section 2).
//
// Contact timing: rcssserver applies a kick in cycle k and shows the ball
// already moved away at k, so the foot meets the ball between k-1 and k
// (the paper's intermediate state): at the half-way frame of cycle k-1,
// with the ball still where it was at k-1.
#pragma once

#include <cstdint>

#include "anim/action_motion.hpp"
#include "proto/world_state.hpp"

namespace mc::anim {

// True when `cur` shows a kick that touched the ball: the kick bit without
// the fault bit and, when the feed carries counters, a new kick command
// since `prev` (a delayed long kick keeps the bit without one).
bool is_successful_kick(const PlayerState* prev, const PlayerState& cur);

// The kicking foot. `ball_lateral_m`: the ball's offset to the body's right
// (m, body space); `dir_lateral`: the kick direction's component to the
// right (unit vector, body space). The foot on the ball's side kicks; a ball
// straight ahead is kicked with the foot that swings across the body
// towards the kick direction (right foot for a kick to the left). Either way
// the support foot goes on the other side of the ball, so the legs never cross.
Foot choose_foot(float ball_lateral_m, float dir_lateral);

struct KickPlanInput {
  float root_x = 0, root_y = 0;   // field m: the 2D root at the contact instant (interpolated)
  float heading = 0;              // field deg: body heading at contact
  float ball_x = 0, ball_y = 0;   // field m: ball when kicked (cycle k-1)
  float after_x = 0, after_y = 0; // field m: ball after the kick (cycle k)
  float ball_radius = 0.085f;     // m
  double contact_time_s = 0;      // stream time of the contact
  float prepare_s = 0.15f;        // how long before contact the motion may begin (look-ahead)
  float speed = 0;                // m/s of the player around the kick (shortens the stance on the support foot)
};

// A kick motion: contact spot for the kicking ankle (so that the front of
// the foot meets the back of the ball), support spot beside and behind the
// ball, and the root offset on the contact frame needed for both legs to
// reach (0 when they reach from the 2D position).
ActionMotion plan_kick(const KickPlanInput& in);

// Merges a kick at `contact_time_s` (stream position `pos`) into `m` when it
// comes within `max_gap_s` of the last kick merged so far: the follow-through
// and the motion are prolonged. Returns false (and leaves `m`) otherwise.
bool merge_kick(ActionMotion& m, double contact_time_s, std::uint64_t pos, double max_gap_s = 0.25);

// Reach used to plan: hip -> ankle (m) with a soft knee.
inline constexpr float kPlanReach = 0.82f;
// Longest step-in (m). It moves the root on the contact frame alone (the
// root lies on the 2D position at both cycles around it), so a longer one
// reads as a jerk; past it, a lower pelvis and a longer stride reach instead.
inline constexpr float kMaxStepIn = 0.3f;
// Horizontal hip -> ankle distance (m) the planner accepts before stepping in.
inline constexpr float kComfortReach = 0.6f;

}  // namespace mc::anim
