// The animator's own bookkeeping of an animated log (issue 4), kept for the
// mocap mode's tests and --compare; the quality tool's figures are issue
// 23's, measured on the stream (close_up_metrics.hpp). Each with its target:
// root error at cycles, planted-foot slide, foot-to-ball distance at kick
// contact, cadence, joint-limit violations and the largest per-frame joint
// jump outside kicks and teleports; also how far a body goes under the grass
// and how far the step-in moves the root on a kick's contact frame.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "anim/animator.hpp"
#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"
#include "proto/world_state.hpp"

namespace mc::anim::tools {

struct Distribution {
  std::vector<double> values;
  double mean() const;
  double percentile(double p) const;  // p in [0, 100]
  double max() const;
};

struct QualityReport {
  Distribution root_error_m;     // |pose root - 2D position| at substep-0 frames, active players
  Distribution slide_m;          // per stance: largest horizontal distance of the ankle from its landing spot
  Distribution contact_m;        // per kick: |distance from the kicking foot's box to the ball's surface|
  Distribution cadence;          // per stride (two steps): steps/s
  Distribution step_in_m;        // per kick: root offset on the contact frame from the mid-point of its neighbours
  double lowest_m = 0;           // lowest point of any drawn segment of any active player (0 = the grass)
  std::string lowest_where;      // frame, player and action of that point
  long limit_violations = 0;     // angles outside their joint's limits (0.01 deg tolerance)
  double max_jump_deg = 0;       // largest |angle change| between frames outside actions and resets
  std::string max_jump_where;    // frame, player and dof of that jump
  long jumps_over_15 = 0;        // joint-frames with a change over 15 deg (same exclusions)
  long joint_frames = 0;         // joint-frames examined for jumps
  double max_jump_swing_deg = 0; // same, leaving out legs whose foot stays planted across the two frames
  double max_head_jump_deg = 0;  // same for the neck and head yaw, which follow the server's neck angle
  std::string max_cadence_where; // frame and player of the fastest stride
  std::string max_slide_where;   // frame and player where the worst stance ended
  long frames = 0, kicks = 0;
};

// Field-space position (x, y, height) of a point given in a joint's local space.
glm::vec3 joint_point_field(const SkeletonDef& skeleton, const PlayerPose& pose, int joint, glm::vec3 local);

// The point of the foot that strikes the ball: front of the foot, mid height (foot local space).
inline constexpr float kStrikeLocal[3] = {0.19f, -0.04f, 0.0f};

// No drawn segment goes further under the grass than this (m): a body rests
// on the grass, it is not buried in it.
inline constexpr double kGroundTolerance = 0.02;
// Largest root offset a step-in may add on a kick's contact frame (m): the
// root leaves its path for that one frame only, so more reads as a jerk.
inline constexpr double kMaxStepInTarget = 0.30;
// Positions are on a 1 cm grid (0.5 cm per axis): in the stream, and in the
// animator's own frames wherever a sole is on the grass (it rounds them,
// anim/grid_rounding.hpp). The step-in, measured from three roots, gets
// that much leeway over its target.
inline constexpr double kStepInQuantM = 0.01;
// Largest per-dof change between frames outside actions and resets (deg):
// issue 23's human angular speed for a leg, 60 deg per 50 ms.
inline constexpr double kMaxJumpTarget = 60.0;

// Measures everything over a whole animated log. `states` are the input in
// stream order (frames refer to them by seq / 2).
QualityReport measure(const SkeletonDef& skeleton, const std::vector<WorldState>& states,
                      const std::vector<PoseFrame>& frames, const std::vector<FrameInfo>& infos,
                      const std::vector<AnimEvent>& events, double ball_radius);

// Human-readable lines, one per metric with its target and PASS/FAIL.
std::string format_report(const QualityReport& r);
// True when every target holds.
bool targets_hold(const QualityReport& r);

}  // namespace mc::anim::tools
