// Locomotion of one player: the posture index of gait_table.hpp advanced by
// the distance covered, cadence and stride from a smoothed speed, and feet
// that stay planted on the grass (field space) while in stance, so that they
// do not slide. A swing is planned relative to the moving body: from where
// the foot left the grass to half a stance ahead of the hip.
//
// Past the paper's limits: the player settles into a standstill with both
// feet down (extra settling steps at a walking cadence, none once both feet
// are under the hips), turns on the spot by stepping, and never exceeds a
// human cadence: above the speed where cadence reaches its cap, the stride
// grows instead, and a touch-down that would come too soon after the same
// foot's previous one waits a frame (hard cap 4.5 steps/s).
//
// At running speed (over one_frame_stance_m per frame, about 3.8 m/s) a foot
// stays down for one frame only: a planted leg sweeps v*dt/leg length per
// frame, which past that speed would exceed the joint speed limit of
// player_animation.hpp (a sprinter's 0.1 s contact is one or two frames at
// 20 frames per second anyway).
#pragma once

#include "anim/gait_table.hpp"
#include "anim/leg_pose_job.hpp"

namespace mc::anim {

struct LocomotionParams {
  float cadence_cap = 4.2f;       // steps/s the stride model aims at; humans sprint at <= 4.5 (anchors D.2)
  float hard_cadence_cap = 4.5f;  // steps/s no foot ever exceeds: a touch-down waits (hovering) if needed
  float speed_halflife_s = 0.25f; // low-pass of the server's speed (anchors D.1: 0.2-0.3 s)
  float max_stance_travel = 0.8f; // m the body may cover over one planted foot
  float one_frame_stance_m = 0.19f; // m per frame (3.8 m/s) above which a foot is down for one frame only
  float settle_cadence = 2.0f;    // steps/s of the steps that bring the feet to rest
  float foot_spacing = 0.11f;     // m, ankle from the body's midline at rest
};

struct FootState {
  bool planted = true;
  float x = 0, y = 0;             // ankle, field m (fixed while planted)
  float from_x = 0, from_y = 0;   // where the swing began, field m
  float yaw = 0, from_yaw = 0;    // sole heading, field deg
  float lift = 0;                 // ankle above its resting height (m)
  float progress = 0;             // swing progress in [0, 1]
  int planted_frames = 0;         // frames since touch-down (gates early steps: cadence)
  float stance_phase = 0;         // cycle fraction covered since touch-down
  int since_landing = 100;        // frames since the previous touch-down
  bool release = false;           // set by the caller: lift this planted foot now (joint speed limit)
  float rel_x = 0, rel_z = 0;     // where the swing began, body space at lift-off (forward, right; m)
};

// Per-player state carried from frame to frame (the caller owns it, as an
// ozz sampling context).
struct LocomotionState {
  bool initialized = false;
  float x = 0, y = 0, heading = 0;  // previous frame's root, field
  float posture_m = 0;              // posture index into the gait table
  float speed = 0;                  // smoothed ground speed, m/s
  float cycle_m = 1.2f;             // current cycle (two steps) length, m
  float pelvis_height = 0.97f;
  float phase_error = 0;            // posture phase still to correct after an off-beat touch-down
  FootState feet[2];                // [0] right, [1] left
  int steps = 0;                    // touch-downs so far (for tests and metrics)
};

struct LocomotionInput {
  float x = 0, y = 0;        // root this frame, field m
  float heading = 0;         // smoothed body heading this frame, field deg
  float dt = 0.05f;          // s since the previous frame
  float move_dx = 0, move_dy = 0;  // unit field direction of travel, (0, 0) when none
  bool rest = false;         // the classifier says stand or turn: bring both feet down
  float stamina = 1;         // 0 exhausted .. 1 fresh
  bool reset = false;        // teleport: put the feet under the body, no steps
};

struct LocomotionOutput {
  float pelvis_height = 0.97f;  // m
  float run = 0;                // 0 walking .. 1 running style
  float amplitude = 0;          // 0 at rest .. 1 in full stride: scales the rhythmic channels
  GaitSample sample;            // rhythmic channels at the posture index
  FootTarget feet[2];           // body space, for LegPoseJob
  bool planted[2] = {true, true};
};

// Step length (m) humans use at a ground speed (m/s), from anchors D.2,
// before the cadence cap; increasing in speed.
float human_step_length(float speed_mps);

// An action (a kick) placed the feet: take them over so that locomotion
// resumes from where they are. Field positions (m) and sole yaws (deg).
// Only the feet with take[i] set are taken over.
void take_over_feet(LocomotionState& state, const float x[2], const float y[2], const float yaw[2],
                    const bool planted[2], const bool take[2]);

// Advances `state` by one frame. Deterministic; no allocation.
void step_locomotion(LocomotionState& state, const LocomotionInput& in, const LocomotionParams& params,
                     LocomotionOutput& out);

}  // namespace mc::anim
