// A kick's contact that the joint speed limit held short (issue 23: the
// kicking foot's box touches the ball). On its contact frame the kicking
// leg may turn at most kMaxKickLegStepDeg a joint; a knee that was bent
// deep in the frame before (a backswing, a step in a turn) then stops
// short of the straight leg the IK asked for, and the foot with it. What
// the knee cannot do the hip can: the whole leg turns about the hip,
// within the hip's own turn and limits, until the foot's box is on the
// ball. Human skeleton only (human_skeleton.hpp); no I/O.
#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "proto/skeleton.hpp"

namespace mc::anim {

// Turns kicking leg `k` ([0] right, [1] left) about its hip so that its
// foot's box comes `gap_m` off the ball (centre `ball_ms` in body space,
// radius `ball_r`), keeping the hip within `cap_deg` of its angles in
// `last` (deg, the last frame) and within its limits. `a`: the pose's
// angles (deg), changed in place; `pelvis_h`: the pelvis joint's height.
// Returns the box's distance from the ball surface it leaves (m).
float reach_ball_with_hip(const SkeletonDef& skel, std::span<const float> last, float pelvis_h, const glm::vec3& ball_ms,
                          float ball_r, int k, float gap_m, float cap_deg, std::span<float> a);

}  // namespace mc::anim
