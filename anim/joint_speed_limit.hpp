// The joint speed limit: how far each joint may turn from one frame to the
// next (issue 23: legs at most 60 deg and arms 45 deg a frame, no pops).
// The limits themselves are player_animation.hpp's (kMaxLegStepDeg,
// kMaxKneeStepDeg, kMaxKickLegStepDeg, kMaxUpperStepDeg); no I/O.
#pragma once

#include <span>

#include "anim/human_skeleton.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

// Scales each joint's change since `last` down to at most its group's
// limit per frame (kMaxKneeStepDeg for a knee, kMaxKickLegStepDeg for
// the leg of `kicking_foot`, 0 right, 1 left, -1 none); `limited` gets
// the joints it held back. A joint whose dofs moved by less than the limit
// in total cannot have rotated further (each elementary rotation adds at
// most its own angle), so only the others are measured.
void limit_joint_speed(const SkeletonDef& skel, const float* last, std::span<float> a, bool limited[kHumanJointCount],
                       int kicking_foot);

}  // namespace mc::anim
