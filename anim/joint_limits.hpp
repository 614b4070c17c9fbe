// Joint limits: angles clamped into each dof's [min, max] of the skeleton.
#pragma once

#include <span>

#include "proto/skeleton.hpp"

namespace mc::anim {

// Clamps each angle into its joint's [min, max]; returns how many were out.
int clamp_to_limits(const SkeletonDef& skeleton, std::span<float> angles);

// The same for the legs' joints only (thighs, shins and feet of
// human_skeleton(), what the leg IK writes): on every player-frame, the
// whole skeleton's took 2.1 % more instructions.
void clamp_legs_to_limits(const SkeletonDef& skeleton, std::span<float> angles);

}  // namespace mc::anim
