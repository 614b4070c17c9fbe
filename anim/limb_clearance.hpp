// Limbs keep out of each other (issue 23: no limbs through limbs), as
// corrections of a pose's joint angles after the legs are solved:
// player_animation.cpp calls them each frame. Human skeleton only
// (human_skeleton.hpp); no I/O.
#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "anim/ankle_travel.hpp"
#include "anim/body_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

// Legs turned out of each other's way may take an ankle this much past a
// frame's travel (m; the pop is 10 cm further). With 1 mm, legs too
// close on the two full games rose from 6/10/9 and 2/5/10 to 21/15/11 and
// 16/13/13; with 4 cm to 11/12/9 and 7/6/10.
inline constexpr float kSeparationSlackM = 0.07f;

// Signed distance (m) from point `p` to the box of segment `seg`, both in
// the segment's joint space (negative inside). With `towards`, the unit
// direction from the box's nearest surface point to `p`.
float box_distance(const Segment& seg, const glm::vec3& p, glm::vec3* towards);

// A hand never sinks into its own side's thigh: the arm is lifted away from
// the body (shoulder abduction) until the hand's box is 6 cm clear of the
// thigh's, and, given the frame before (`last`, the same size as `a`), 1 cm
// clear at a third and two thirds of the clients' blend from it. `a`: the
// pose's angles (deg), changed in place. `near` ([0] right, [1] left):
// whether each hand was within 8 cm of its thigh in the frame before (the
// blend is checked then too), set to whether it is in this one as it came.
void keep_hands_off_thighs(const SkeletonDef& skel, std::span<float> a, std::span<const float> last = {},
                           bool* near = nullptr);

// How deep (m, negative: outside) side `side`'s hand (0 right, 1 left) is
// in its own side's thigh: in the pose `a` and, given the frame before
// (`last`, the same size), at a third and two thirds of the clients' blend
// from it, the deepest of the three. Read only to -`far` m: a hand further
// out reads -`far`.
float hand_depth_in_thigh(const SkeletonDef& skel, std::span<const float> a, std::span<const float> last, int side,
                          float far = 0.08f);

// The legs' centre lines (thighs, shins, feet) keep half a box width apart
// plus a margin: a leg in the air is turned out at the hip (with both in
// the air, the one further across the body's midline). True when a leg
// in `planted` ([0] right, [1] left) is on the grass and the legs were too
// close: the caller then turns the planted knees out (LegPoseJob's
// knee_out_deg). `a`: the pose's angles (deg); `pelvis_h`: the pelvis
// joint's height (m).
bool separate_legs(std::span<float> a, float pelvis_h, const bool planted[2]);

// How far past the legs' joint speed limit a hip may turn to keep the legs
// apart after that limit (deg; separate_legs_again, keep_legs_apart_drawn).
inline constexpr float kSeparateAgainDeg = 8.0f;

// The hip (0 right, 1 left) that turns more than `most_deg` from `last` to
// `a`, or more than a third of it in a third of the clients' blend; -1
// when neither does. With `only` >= 0, that hip alone is checked.
int hip_turning_too_fast(std::span<const float> last, std::span<const float> a, float most_deg, int only = -1);

// Legs brought together again after separate_legs (by the joint speed
// limit, or by a whole-body action's leg pose blended over them): a leg in
// the air is turned out of the other leg's way once more, as long as each
// hip then turns at most kSeparateAgainDeg past the limit (issue 23's
// largest change is 60 deg a frame) and, with `travel`, each ankle keeps
// within a frame's travel (plus kSeparationSlackM), and each third of the
// clients' blend of a hip within a third of that. Otherwise the leg turns
// out as far as those limits let it; if not at all, the legs stay as they
// were, but for both feet up: then the leg that turned too fast is held and
// the other one turns out.
// On the two full games: thighs / shins / feet too close 8/9/10 -> 4/4/3
// and 2/5/10 -> 0/1/3 at 20 Hz (with a whole-body action's blend, below);
// with 10 deg the legs' largest change at 60 Hz went to 61.2 deg
// (anim/README.md).
void separate_legs_again(const SkeletonDef& skel, const BodyFrame& body, float pelvis_h, std::span<const float> last,
                         const AnkleTravel* travel, const bool planted[2], std::span<float> a);

}  // namespace mc::anim
