// A kick's contact: the kicking foot's box touches the ball (issue 23).
// touch_ball solves the leg onto it; on the contact frame the kicking
// leg may turn at most kMaxKickLegStepDeg a joint; a knee that was bent
// deep in the frame before (a backswing, a step in a turn) then stops
// short of the straight leg the IK asked for, and the foot with it. What
// the knee cannot do the hip can: the whole leg turns about the hip,
// within the hip's own turn and limits, until the foot's box is on the
// ball, neither short of it nor in it. Human skeleton only
// (human_skeleton.hpp); no I/O.
#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "anim/action_motion.hpp"
#include "anim/body_frame.hpp"
#include "anim/leg_pose_job.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

// The foot's box this far off the ball's surface at contact (m): the
// margin of the stream's quantization.
inline constexpr float kContactGapM = 0.004f;

// Moves kicking foot `k` ([0] right, [1] left) of `act`'s contact so that
// its box lies kContactGapM off the ball: corrections of its ankle target
// in `legs` along the contact normal, each solved again by LegPoseJob, the
// pelvis sinking (a lunge) where the leg cannot reach. `body` places the
// ball; `a` holds the pose; `pelvis_h` gets the pelvis's new height.
void touch_ball(const SkeletonDef& skel, const BodyFrame& body, float& pelvis_h, const ActionSample& act, int k,
                LegPoseJob& legs, std::span<float> a);

// A foot deeper than this in the ball (m) is turned back out to the
// contact gap too: the ankle the limit held short of its pitch can bring
// the box's heel or toe into the ball (game 1 seq 7817, 2.0 cm deep, a
// sole levelled out of the grass on the frame before). Shallower, it is
// within the stream's quantization and left.
inline constexpr float kDeepInBallM = 0.01f;

// Turns kicking leg `k` ([0] right, [1] left) about its hip so that its
// foot's box comes `gap_m` off the ball (centre `ball_ms` in body space,
// radius `ball_r`), from further off or from deeper in than kDeepInBallM,
// keeping the hip within `cap_deg` of its angles in `last` (deg, the last
// frame) and within its limits. `a`: the pose's
// angles (deg), changed in place; `pelvis_h`: the pelvis joint's height.
// Returns the box's distance from the ball surface it leaves (m).
float reach_ball_with_hip(const SkeletonDef& skel, std::span<const float> last, float pelvis_h, const glm::vec3& ball_ms,
                          float ball_r, int k, float gap_m, float cap_deg, std::span<float> a);

}  // namespace mc::anim
