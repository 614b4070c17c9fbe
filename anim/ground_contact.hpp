// The lowest point of a posed body: the drawn segments (boxes and spheres of
// the skeleton definition, proto/skeleton.hpp) after forward kinematics.
//
// Used three times: whole-body actions (tackle, catch, dive) rest the body on
// the grass by raising the pelvis until nothing is under it, the quality tool
// reports how far any frame's body went below the grass, and the clients
// rest each pose they draw between two frames on it (rest_on_grass).
#pragma once

#include <cmath>
#include <cstdint>
#include <span>

#include <glm/mat4x4.hpp>

#include "anim/human_skeleton.hpp"
#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

// Lowest height (model space Y, m; 0 is the grass) reached by any joint's
// segment. `models` holds one model-space transform per joint of `skeleton`
// (LocalToModelJob's output). Boxes count with their 8 corners, spheres with
// their bottom; joints without a segment (size 0) count with their origin.
// `mask` (bit i for joint i) limits the joints looked at.
float lowest_point_ms(const SkeletonDef& skeleton, std::span<const glm::mat4> models, std::uint32_t mask = ~0u);

// Joint masks of human_skeleton() for LocalToModelJob::joint_mask and the above.
inline constexpr std::uint32_t kAllJoints = ~0u;
inline constexpr std::uint32_t kFeetJoints = (1u << kRFoot) | (1u << kLFoot);
inline constexpr std::uint32_t kLegJoints = (1u << kPelvis) | (1u << kRThigh) | (1u << kRShin) | (1u << kLThigh) |
                                            (1u << kLShin) | kFeetJoints;

// What a client does to each pose it draws (issue 23; proto/SPEC.md, "Drawing
// between frames"): blending two frames' angles can take a sole a few
// centimetres under the grass between them, so the body is raised by what
// lies deeper than `tolerance_m`. Returns the lift (m, 0 when nothing is
// that deep). Any skeleton of the hello; the pose's root height changes.
inline constexpr float kGrassToleranceM = 0.01f;
float rest_on_grass(const SkeletonDef& skeleton, PlayerPose& pose, float tolerance_m = kGrassToleranceM);

// The same for every player of a drawn frame (the viewer's, the quality
// tool's 60 Hz measurement); players not on the pitch (no side) are left.
void rest_on_grass(const SkeletonDef& skeleton, PoseFrame& frame);

// Lowest point (model-space Y, m) of joint `j`'s own segment.
float segment_lowest_ms(const Segment& segment, const glm::mat4& model);

// Turns the ankle of foot joint `foot` (its first dof, the pitch, at angle
// index `ankle_dof`) towards a level sole by as little as lifts the sole out
// of the grass, within the joint's limits and [lo_deg, hi_deg] (a joint
// speed limit, say); rewrites that angle and the foot's model transform.
// With `clear_m` the sole is lifted to that height rather than to the grass
// (a foot in the air skimming it). Returns the foot's lowest point
// afterwards (m; < clear_m when even the most level sole allowed is lower,
// e.g. an ankle below its own height).
float level_foot(const SkeletonDef& skeleton, std::span<glm::mat4> models, std::span<float> angles, int foot,
                 int ankle_dof, float lo_deg = -INFINITY, float hi_deg = INFINITY, float clear_m = 0.0f);

// Lowest ankle height (m) at which a sole pitched by `pitch_deg` (+ toes up)
// keeps both its heel and its toe on or above the grass: a pitched foot
// rolls over its heel or its toes instead of sinking into the ground.
float min_ankle_height(float pitch_deg);

}  // namespace mc::anim
