// The close-up metrics of issue 23, measured on what a spectator receives
// (stream_view.hpp): decoded frames posed by forward kinematics on the
// hello's skeleton, the kicks of the "kick" control messages. Nothing here
// reads the animator's internal state; the one exception is the
// joint-limit check, which must look at the animator's output because the
// encoder clamps every angle into its limits.
//
// Definitions (each figure is per "drawn frame": the 20 Hz frames
// themselves, or the clients' linear blend at `draws_per_frame` times the
// rate, stream_view.hpp):
//   - sole: the bottom face of a foot's box (joints "r_foot", "l_foot"). A foot
//     is grounded when the lowest corner of its sole is below 3 cm; no speed
//     gate. Its contact point is the centroid of the sole corners within 1 cm
//     of the lowest (weighted by closeness: a flat sole's centre, a heel's or a
//     toe's edge), fixed in the foot at the earlier of two frames.
//   - grounded-foot speed: how fast that point moves horizontally between two
//     drawn frames on which the foot is grounded, by the root's speed over the
//     same two frames (speed bands of 1 m/s; "stand" below 0.5 m/s).
//   - teleport: a root jump over 1 m between two 20 Hz frames; pairs across a
//     teleport, or with the player inactive on either side, are left out of
//     every frame-to-frame figure.
//   - joint change: the rotation angle between a joint's local rotations on
//     two drawn frames, in degrees per 50 ms (a 20 Hz frame); the pelvis with
//     the heading. Legs: thighs, shins, feet; arms: upper and lower arms,
//     hands; trunk: pelvis, torso; head: neck and head.
//   - ankle pop: an ankle moving more than 1 m in 50 ms, or more than 0.6 m
//     relative to the pelvis.
//   - clearance: distance between the centrelines (the longest axis, end to
//     end) of two leg segments' boxes, closer than half the larger box width
//     counts; thighs, shins, feet with their opposite, and the crossed pairs.
//     A hand's depth: how far the deepest point of its box is inside the
//     pelvis, the torso or a thigh.
//   - kick: the signed distance from the named foot's box to the ball's
//     surface at contact_time_ms (negative: inside the ball); also from the
//     toe tip (the centre of the box's front face).
//   - floating: both feet more than 10 cm up while the root moves slower than
//     2 m/s.
//   - at a limit: an angle within 0.5 deg of its joint's min or max; per
//     joint, the share of active player-frames with any of its dofs there.
//   - cadence: touch-downs (a foot becoming grounded) per second over 2-s
//     windows (one per second) of an active player with no teleport, windows
//     with at least one touch-down.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "anim/tools/metrics.hpp"
#include "anim/tools/stream_view.hpp"
#include "proto/world_state.hpp"

namespace mc::anim::tools {

inline constexpr int kSpeedBands = 11;
// "stand (< 0.5)", "0.5-1", "1-2", ..., "8-9", "9+" (m/s of the root).
const char* speed_band_name(int band);
int speed_band(double root_speed_mps);

// Thresholds of the definitions above and the targets of issue 23.
namespace close_up {
inline constexpr double kGroundedBelowM = 0.03;
inline constexpr double kTeleportM = 1.0;
inline constexpr double kFloatAboveM = 0.10;
inline constexpr double kFloatSlowerMps = 2.0;
inline constexpr double kAtLimitDeg = 0.5;
inline constexpr double kAnklePopM = 1.0, kAnklePopRelM = 0.6;
inline constexpr double kHandDepthM = 0.02;
// Targets.
inline constexpr double kGroundedMeanMps = 0.5, kStandMeanMps = 0.2;
inline constexpr double kKickP95M = 0.02, kKickMaxM = 0.03, kKickInsideM = 0.02;
inline constexpr double kLegStepDeg = 60, kArmStepDeg = 45;
// The trunk and the head (neck and head joints) turn no faster than the arms
// swing: 900 deg/s.
inline constexpr double kTrunkStepDeg = 45, kHeadStepDeg = 45;
inline constexpr long kMaxFloatingPlayerFrames = 50;  // at 20 Hz; scaled by draws_per_frame
inline constexpr double kAnkleLimitShare = 0.02;
inline constexpr double kCadenceP99 = 4.5;
}  // namespace close_up

struct CloseUpReport {
  int draws_per_frame = 1;  // 1: the 20 Hz frames; 3: drawn at 60 Hz
  long frames = 0;          // drawn frames
  long player_frames = 0;   // active player-frames among them
  // 1. Grounded feet, by the root's speed band.
  std::array<Distribution, kSpeedBands> grounded_mps;
  std::array<long, kSpeedBands> grounded_over_half{};  // frame pairs above 0.5 m/s
  double grounded_worst_mps = 0;
  std::string grounded_worst_where;
  // 2. Kicks at contact.
  Distribution kick_box_m;  // signed: foot box to ball surface, negative inside
  Distribution kick_toe_m;  // signed: toe tip to ball surface
  long kicks_inside = 0;    // more than 2 cm inside the ball
  std::string kick_worst_where;
  // 3. Pops: per active player-frame, the largest change in each group (deg per 50 ms).
  Distribution leg_step_deg, arm_step_deg, trunk_step_deg, head_step_deg;
  long legs_over_50 = 0, legs_over_60 = 0, arms_over_45 = 0, arms_over_50 = 0, trunk_over_45 = 0, head_over_45 = 0;
  std::string leg_worst_where, arm_worst_where, trunk_worst_where, head_worst_where;
  long ankle_pops = 0;  // foot-frames
  double ankle_step_max_m = 0;
  // 4. Clearance: player-frames with a pair closer than half a box width.
  long thighs_close = 0, shins_close = 0, feet_close = 0, crossed_close = 0;
  long hands_inside = 0;  // player-frames with a hand more than 2 cm inside the body or a thigh
  double hand_depth_max_m = 0;
  std::string clearance_worst_where, hand_worst_where;
  // 5. Floating.
  long floating = 0;
  double floating_max_m = 0;
  std::string floating_where;
  // 6. Time at the limits (20 Hz frames only).
  double ankle_limit_share = 0;  // the worse ankle
  double worst_limit_share = 0;  // the worst joint of all
  std::string worst_limit_joint;
  // Cadence from touch-downs.
  Distribution cadence;
  // Issue 4's targets that still hold: root at cycles, joint limits (of the
  // animator's output), nothing under the grass, the step-in.
  Distribution root_error_m;
  long limit_violations = 0;
  double lowest_m = 0;
  std::string lowest_where;
  Distribution step_in_m;
  long kicks = 0;
};

// Measures `view` at `draws_per_frame` drawn frames per 20 Hz frame (1 or
// more). `states`: the log's 10 Hz states (root error at cycles, by
// seq / 2); `produced`: the animator's frames before encoding (joint limits).
// How drawn frames between two 20 Hz ones are blended: as the clients do
// (joint angles linearly, then the feet kept on their line or raised off the
// grass, anim/leg_blend.hpp), or, to measure what that step gives, without it.
// `draw_phase`: where the drawn frames fall, as a fraction of one drawn
// frame past each 20 Hz frame (0 <= phase < 1; 0: on the 20 Hz frames and
// at k / draws_per_frame between them). A display's clock is not locked to
// the stream's, so a viewer sees every phase; 0 was the most favourable of
// 0, 0.25, 0.5 and 0.75 on the full games (anim/README.md), as the
// animator checks its own frames at the same points.
enum class DrawnLegs { AngleBlendOnly, LegBlend };
CloseUpReport measure_close_up(const StreamView& view, const std::vector<WorldState>& states,
                               const std::vector<PoseFrame>& produced, int draws_per_frame,
                               DrawnLegs legs = DrawnLegs::LegBlend, double draw_phase = 0.0);

// The report as a table: one column per report (20 Hz, then the drawing rate).
std::string format_close_up(const std::vector<const CloseUpReport*>& reports);
// True when every target of issue 23 holds.
bool close_up_targets_hold(const CloseUpReport& r);
// The grounded-foot mean of a band (0 when the band is empty).
double band_mean(const CloseUpReport& r, int band);

}  // namespace mc::anim::tools
