// One player's pose at one frame: footsteps (footsteps.hpp) for the feet and
// the rhythm of the body, the legs solved onto the feet by IK with the pelvis
// coming down where a leg cannot reach and a heel rising where an ankle
// cannot bend, the head on the server's gaze, and an optional action motion
// (kick, tackle, catch, dive; action_motion.hpp) layered over it.
//
// Transitions blend (Bollo, "High-Performance Animation Transitions in Gears of
// War", GDC 2016; the decaying spring of Holden's Motion-Matching, spring.h):
// where the upper body's target jumps (an action starts, ends or gives way to
// another), the jump becomes an offset that dies away in about 0.2 s.
//
// No pops: the heading turns at most kMaxTurnPerFrameDeg, and every joint
// rotates at most its group's limit per frame (legs kMaxLegStepDeg, arms,
// trunk and head kMaxUpperStepDeg: human angular speeds, a sprinter's knee
// peaks near 1 000 deg/s), on teleports too unless the root jumped. Where
// that limit holds a planted leg back, its foot is released (it lifts from
// where it is) rather than dragged.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "anim/action_motion.hpp"
#include "anim/ankle_travel.hpp"
#include "anim/anim_events.hpp"
#include "anim/classifier.hpp"
#include "anim/footsteps.hpp"
#include "anim/leg_blend.hpp"
#include "anim/motion_source.hpp"
#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::proto {
class Quantizer;
}

namespace mc::anim {

// Per-player context carried across frames (owned by the Animator).
struct PlayerAnim {
  FootstepState loco;
  float pelvis_height = 0.975f;  // previous frame's pelvis height (m)
  float heading = 0;           // heading of the previous frame, field deg (rate-limited)
  std::array<float, dof::kCount> last_angles{};  // previous frame's output (joint speed limit)
  // Inertialization of the upper body (pelvis, torso, head, arms): the
  // offset still to decay and its velocity, per dof, and what the action
  // layer added to each last frame.
  std::array<float, dof::kRHip> blend_x{}, blend_v{}, last_layer{};
  bool was_in_action = false;
  bool last_planted[2] = {false, false};
  bool hands_near[2] = {false, false};  // a hand within 8 cm of its thigh last frame (keep_hands_off_thighs)
  AnkleTravel ankles;  // last frame's ankles and pelvis (ankle_travel.hpp)
  PlayerPose last_sent;  // last frame as it left (drawn_leg_clearance.hpp)
  // The action playing or about to play (kick_planner.hpp), and its bookkeeping.
  ActionMotion motion;
  bool motion_active = false;
  // An action planned while a kick still waits for its contact: it takes
  // over once that contact has been shown.
  ActionMotion next_motion;
  bool next_pending = false;
  std::uint64_t last_action_pos = 0;  // stream position + 1 of the last action planned or merged
  std::uint64_t ball_contact_pos = 0;  // the ball waits on the half-way frame before this cycle
  bool kick_event_pending = false;    // a Kick event waits for its contact frame
  AnimEvent kick_event;
  Action action = Action::Stand;
  bool was_active = false;
  // Mocap mode's slow walk (motion_source.hpp): the cursor in the captured
  // walk, its blend weight over the keyframe gait, and its planted feet (field m).
  WalkCursor walk;
  float walk_w = 0;
  bool walk_planted[2] = {false, false};
  bool walk_lockout[2] = {false, false};  // let go mid-stance: not planted again before it lifts
  std::uint8_t walk_since_land[2] = {255, 255};  // frames since the foot last landed (255: long ago)
  float walk_off[2][2] = {{0, 0}, {0, 0}};  // held spot - capture's foot (body x, z): the swing starts from it
  std::uint8_t walk_idle = 255;  // frames since the walk last showed (its cadence guard lasts 1 s)
  float walk_foot_x[2] = {0, 0}, walk_foot_y[2] = {0, 0};
};

// Fastest turn of the body between two frames: a half turn in 0.75 s, so
// that a planted leg twists within the joint speed limit; the server allows 180 deg per cycle.
inline constexpr float kMaxTurnPerFrameDeg = 12.0f;
// Fastest rotation of a joint between two frames (deg per 50 ms): legs 1 000
// deg/s (a sprinter's knee; the knee itself a little more, below), arms,
// trunk, neck and head 760 deg/s. Issue 23's limits are 60 and 45; the
// margin covers the stream's quantization.
inline constexpr float kMaxLegStepDeg = 50.0f;
// The knee alone may turn further: at 50 deg it held a sprinter's swing
// knee short of folding after toe-off, and the foot, behind a leg still
// nearly straight, hung a few centimetres over the grass while it
// travelled 0.5-0.8 m (game 1 seq 7525, right 11: 4 mm up): a foot that
// slides, at 20 Hz and in the clients' blend. 56 deg (1 120 deg/s, 12 %
// over the figure above) took game 1's 60 Hz grounded-foot band of 8-9
// m/s at the display's phases 0.35-0.75 from 0.52-0.54 to 0.47-0.51 m/s,
// and the 9+ band at all eight from 0.44-0.52 to 0.40-0.48 (anim/README.md,
// "A knee's own speed"); a leg's largest turn stays under issue 23's 60.
inline constexpr float kMaxKneeStepDeg = 56.0f;
// The kicking leg on its contact frame: a kick is a leg's fastest motion
// (knee extension near impact 1,500-2,300 deg/s in instep kicks, the
// studies reviewed by Lees & Nolan 1998, J Sports Sci 16:211). Held at the
// sprinter's 50 deg, a leg that swings a long way into the ball (a kick
// while turning) stops short of it. 57 deg (1 140 deg/s) keeps the margin
// under issue 23's 60 for the stream's quantization.
inline constexpr float kMaxKickLegStepDeg = 57.0f;
inline constexpr float kMaxUpperStepDeg = 38.0f;

struct PlayerFrameInput {
  float x = 0, y = 0;          // root, field m (already interpolated)
  float heading = 0;           // smoothed body heading, field deg (animate_player rate-limits it)
  float body = 0;              // server body angle, field deg (interpolated between cycles)
  float neck = 0;              // server neck angle relative to the body, deg (interpolated)
  float move_dx = 0, move_dy = 0;  // direction of travel, field (any length; 0 when none)
  Action action = Action::Stand;   // smoothed decision of this cycle
  float stamina = 1;           // 0..1
  bool reset = false;          // teleport or (re)connection: feet under the body
  bool animate_locomotion = true;  // detail level: false -> glide standing
  float dt = 0.05f;
  const ActionSample* layer = nullptr;  // an action layered over locomotion at this frame, or null
  const MotionSource* source = nullptr;  // mocap mode: slow walking from its walk(), or null
  // The stream's grid: the pose leaves on it, rounded so that its ankles stay
  // put (grid_rounding.hpp); null leaves it unrounded.
  const proto::Quantizer* grid = nullptr;
  // The clients' step between frames (proto/SPEC.md 4.7 step 2): with it,
  // the legs are kept apart as the clients draw the frame from the last
  // one (drawn_leg_clearance.hpp); null leaves that unchecked.
  const LegBlend* drawn_legs = nullptr;
  // The root at the following frames (field m), as far as the look-ahead
  // knows them: where the feet will have to be.
  float ahead_x[kPathAhead] = {}, ahead_y[kPathAhead] = {};
  int ahead_n = 0;
};

// Writes x, y, z, heading and the angles of `out` (side, unum, state are the
// caller's). `limits_from` clamps every angle into its joint limits.
// `planted` (optional) receives which feet locomotion keeps fixed on the grass.
void animate_player(PlayerAnim& ctx, const PlayerFrameInput& in, const FootstepParams& step_params,
                    const SkeletonDef& limits_from, PlayerPose& out, bool* planted = nullptr);

}  // namespace mc::anim
