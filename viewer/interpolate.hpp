// Blending two pose frames at render time, so that 20 Hz frames play
// smoothly at any display rate. The same rules as the web page
// (web/src/model/interp.js), so both clients show the same motion:
// positions and joint angles linearly, the heading the short way round,
// discrete data (play mode, score, state bits) from `a` until t reaches 1,
// and a player who jumps more than 5 m (a move at kick-off) is not slid
// across the pitch: he switches at t = 0.5.
#pragma once

#include "anim/leg_blend.hpp"
#include "proto/pose_frame.hpp"

namespace mc::viewer {

inline constexpr float kTeleportMetres = 5.0f;

// Field degrees from p towards q the short way round, at t.
float lerp_heading(float p, float q, float t);

// Writes the blend of `a` and `b` at `t` (clamped to [0, 1]) into `out`;
// `dof_count` angles per player are blended (the rest are copied from a).
// With `feet`, planted feet then keep to their line and lifting ones clear
// the grass (proto/SPEC.md 4.7 step 2).
void blend_frames(const PoseFrame& a, const PoseFrame& b, float t, int dof_count, PoseFrame& out,
                  const anim::LegBlend* feet = nullptr);

}  // namespace mc::viewer
