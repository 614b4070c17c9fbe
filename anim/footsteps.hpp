// Footsteps: where each foot is, for every gait from standing to a sprint.
// A planted foot is a fixed spot on the grass: it rolls over its heel edge
// or its toe edge but never slides; the leg reaches it by IK and the pelvis
// comes down where the leg cannot (player_animation.cpp). A foot in the air
// swings in field space from where it left the grass to where it lands: it
// rises and comes down nearly vertically and travels in between, so that a
// client blending two frames does not drag it along the grass.
//
// Timing comes from human data (gait_timing.hpp): a gait phase advances at
// half the cadence for the player's speed; the right foot lands at phase 0,
// the left at 0.5, and each stays down for the duty factor of the stride.
// Walking keeps both feet down in turn, running has a flight phase. The
// landing spot is under the hip at mid-stance: where the root will be half
// a stance after the touch-down, read from the path ahead (the animator's
// look-ahead) and extrapolated past it, plus the hip's side offset, and never
// on the other foot's side. A planted foot leaves early when the hip is about
// to move out of its reach (it pushes off), and lands no sooner than a human
// cadence allows after its previous landing.
//
// Standing: below 0.3 m/s the feet settle with short steps onto their resting
// spots under the hips and stop. Turning on the spot pivots on a planted foot
// (its sole turns about its centre) while the other steps round.
//
// Past Virtual RoboCup's keyframe locomotion (the posture index of
// gait_table.hpp still drives the rhythm of pelvis, torso and arms), after
// the foot locking of Holden's Motion-Matching (orangeduck/Motion-Matching,
// controller.cpp: contact_update, locked contact points released by
// distance) with the release planned ahead instead of blended afterwards.
#pragma once

#include "anim/gait_table.hpp"
#include "anim/gait_timing.hpp"
#include "anim/leg_pose_job.hpp"

namespace mc::anim {

struct FootstepParams {
  // Steps/s the stride model aims at. Sprinters reach 4.3-4.5 (Dorn et al.),
  // but at 20 frames per second touch-downs fall on frames: a foot landing
  // every 9 frames shows 5 steps/s in a 2-s window, every 10 frames 4.
  float cadence_cap = 4.0f;
  float hard_cadence_cap = 4.0f;  // a foot lands no sooner than 2 / this after its own previous landing
  float foot_spacing = 0.11f;     // m, ankle from the body's midline at rest
  float min_gap = 0.17f;          // m sideways between the two soles' centres when one lands (soles 0.10 wide)
  float reach = 0.83f;            // m, hip -> ankle that a leg keeps a soft knee at
  float idle_speed = 0.3f;        // m/s below which the feet settle and stop
  float rest_tolerance = 0.07f;   // m from its resting spot that a settled foot may be
  float rest_yaw_tolerance = 25;  // deg
  float pivot_deg = 30;           // a planted foot turned further from the heading pivots...
  float pivot_rate_deg = 9;       // ...by at most this per frame (about its sole's centre)
};

struct FootState {
  bool planted = true;
  // Planted: the sole's centre on the grass (field m), its yaw (field deg)
  // and its roll (deg, + toes up: back on the heel edge; - heel raised: up on
  // the toe edge). The edge it rolls over stays where it is.
  float x = 0, y = 0, yaw = 0, pitch = 0;
  // In the air: the ankle (field x, y, height) where it left the grass and
  // where it will land, with the sole's yaw and pitch at both ends.
  float ax = 0, ay = 0, ah = 0, ayaw = 0, apitch = 0;
  float bx = 0, by = 0, byaw = 0, bpitch = 0;
  float cx = 0, cy = 0;       // where the ankle is over the grass now (field m)
  float u = 0;                // swing progress in [0, 1]
  int extra = 0;              // frames the swing went on past its end (spot not reached yet)
  float phase_left = 0.5f;    // gait phase still to go at lift-off (the swing's length in phase)
  float lift = 0.1f;          // how high this swing lifts the ankle above the straight line (m)
  float stance_s = 0;         // s on the grass since touch-down
  int since_landing = 100;    // frames since the last touch-down (cadence guard)
  bool release = false;       // set by the caller: lift this planted foot now (joint speed limit)
  bool leaving = false;       // planted, out of the hip's reach from the next frame: lifts then
  bool hurry = false;         // the other foot waits for this one to land
  bool held = false;          // set by the caller: this foot is an action's (a kick's); leave it be
};

// Per-player state carried from frame to frame (owned by the caller).
struct FootstepState {
  bool initialized = false;
  float x = 0, y = 0, heading = 0;  // previous frame's root (field) and heading
  float vx = 0, vy = 0;             // root velocity along the path (m/s, field), smoothed
  float speed = 0;                  // smoothed speed (m/s) the gait is chosen for
  float phase = 0;                  // gait phase in [0, 1): right touch-down at 0, left at 0.5
  bool moving = false;              // the gait phase runs (false: standing, settling steps only)
  float run = 0;                    // 0 walking .. 1 running style, smoothed
  float pelvis_height = 0.975f;
  float cycle_m = 1.2f;             // stride (two steps) length of the current gait, m
  FootState feet[2];                // [0] right, [1] left
  int steps = 0;                    // touch-downs so far
};

// Where the root will be: field positions at the frames after this one
// (index 0 is the next frame), from the look-ahead; beyond them the path is
// extrapolated.
inline constexpr int kPathAhead = 8;

struct FootstepInput {
  float x = 0, y = 0;        // root this frame, field m
  float heading = 0;         // body heading this frame, field deg (already smoothed)
  float dt = 0.05f;          // s per frame
  float ahead_x[kPathAhead] = {}, ahead_y[kPathAhead] = {};
  int ahead_n = 0;           // valid entries of ahead_x/ahead_y
  bool rest = false;         // the classifier says stand or turn: settle, do not stride
  float stamina = 1;         // 0 exhausted .. 1 fresh
  bool reset = false;        // teleport: put the feet under the body, no steps
};

struct FootstepOutput {
  float pelvis_height = 0.975f;  // m, before the legs' reach is applied (player_animation.cpp)
  float run = 0;                 // 0 walking .. 1 running style
  float amplitude = 0;           // 0 at rest .. 1 in full stride: scales the rhythmic channels
  GaitSample sample;             // rhythmic channels at the gait phase
  FootTarget feet[2];            // ankle targets, body space, for LegPoseJob
  bool planted[2] = {true, true};
  float sole_h[2] = {0, 0};      // lowest sole height of each foot's target (m, 0 on the grass)
  // A foot in the air reaching down for the grass (both feet up on a frame
  // too slow for a flight): the pelvis comes down for it as for a planted one.
  bool reaching[2] = {false, false};
};

// Ankle (field x, y, height) of a planted foot: sole centre (x, y), yaw,
// roll `pitch` (see FootState).
void planted_ankle(float x, float y, float yaw_deg, float pitch_deg, float& ax, float& ay, float& ah);

// An action (a kick) placed a foot: take it over so that the footsteps
// resume from it. Field m, yaw field deg, pitch deg; `planted` with the sole
// on the grass (x, y: its centre), else the ankle at (x, y, h) in the air.
void take_over_foot(FootstepState& state, int foot, float x, float y, float h, float yaw, float pitch, bool planted);

// The same for both feet given by their ankles (field m) with level soles:
// the feet with take[i] set, planted or in the air.
void take_over_feet(FootstepState& state, const float ankle_x[2], const float ankle_y[2], const float yaw[2],
                    const bool planted[2], const bool take[2]);

// Advances `state` by one frame. Deterministic; no allocation.
void step_footsteps(FootstepState& state, const FootstepInput& in, const FootstepParams& params,
                    FootstepOutput& out);

}  // namespace mc::anim
