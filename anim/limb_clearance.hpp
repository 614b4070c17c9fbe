// Limbs keep out of each other (issue 23: no limbs through limbs), as
// corrections of a pose's joint angles after the legs are solved:
// player_animation.cpp calls them each frame. Human skeleton only
// (human_skeleton.hpp); no I/O.
#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "proto/skeleton.hpp"

namespace mc::anim {

// Signed distance (m) from point `p` to the box of segment `seg`, both in
// the segment's joint space (negative inside). With `towards`, the unit
// direction from the box's nearest surface point to `p`.
float box_distance(const Segment& seg, const glm::vec3& p, glm::vec3* towards);

// A hand never sinks into its own side's thigh: the arm is lifted away from
// the body (shoulder abduction) until the hand's box is 6 cm clear of the
// thigh's. `a`: the pose's angles (deg), changed in place.
void keep_hands_off_thighs(const SkeletonDef& skel, std::span<float> a);

// The legs' centre lines (thighs, shins, feet) keep half a box width apart
// plus a margin: a leg in the air is turned out at the hip (with both in
// the air, the one further across the body's midline). True when a leg
// in `planted` ([0] right, [1] left) is on the grass and the legs were too
// close: the caller then turns the planted knees out (LegPoseJob's
// knee_out_deg). `a`: the pose's angles (deg); `pelvis_h`: the pelvis
// joint's height (m).
bool separate_legs(std::span<float> a, float pelvis_h, const bool planted[2]);

}  // namespace mc::anim
