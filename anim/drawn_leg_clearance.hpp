// Legs kept apart as the clients draw a frame (issue 23: no limbs through
// limbs, at the clients' drawing rate as well as at 20 Hz). Human skeleton
// only (human_skeleton.hpp); no I/O.
//
// The clients blend two frames and then keep the legs apart themselves
// (proto/SPEC.md 4.7 step 2), but only as far as a leg's turn over the
// frame and its ankle's travel leave room: a leg swinging fast past a
// planted one has none left, and passes through it (anim/README.md). Only
// the frame can give it room: this step draws the frame from the last one
// exactly as the clients do (anim::LegBlend) and, where the legs come too
// close, turns a leg in the air at the hip at this frame, so that the
// blend carries it wide of the other one.
#pragma once

#include <cmath>
#include <span>

#include "anim/ankle_travel.hpp"
#include "anim/leg_blend.hpp"
#include "proto/pose_frame.hpp"
#include "proto/quantizer.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

// The blend's legs keep this far beyond half the wider box's width (m).
// The stream rounds the frame after this check (1 deg on a hip moves a
// knee 0.8 cm), so a few cases come back a few millimetres inside; 1.5 cm
// cleared more of them but took the 4-6 m/s grounded-foot bands at 60 Hz
// 0.01-0.02 m/s higher (anim/README.md).
inline constexpr float kDrawnApartM = 0.005f;

// `last`: the previous frame as it left the animator, and `grid` the
// stream's (the blend is drawn from `last` as the stream carries it,
// as_streamed below; null: as it is). `last_angles`: its angles before the
// stream's rounding, which the joint speed limit holds this frame to.
// `now`, `a`: this frame's root and angles (`a` changed in place).
// `planted` ([0] right, [1] left): the feet on the grass at this frame,
// whose legs stay as they are.
// The blend is checked over the whole frame, since a display draws it at
// any phase: at kDrawnSteps points, then between them wherever the legs
// come within 5 cm, and densely where the clients' step turns the way it
// parts the feet (drawn_leg_clearance.cpp).
// Where its legs come closer than kDrawnApartM, a leg in the air turns at
// the hip, kDrawnStepDeg at a time up to kDrawnMostDeg: forward or back
// (flexion), out (abduction), across (a leg crossed over the other one),
// or about its own axis (a toe or heel out of the other foot's way); or it
// bends or straightens its knee as far. A turn is refused when the hip
// would turn faster than the joint speed limit plus kSeparateAgainDeg (or
// a third of that in a third of the frame), or the knee faster than its
// own (kMaxKneeStepDeg), when the frame's own legs would come closer, when an ankle would
// pop as drawn where it did not, when a foot on the grass would be
// carried further over it, or when the thigh would come within 1 cm of
// its own side's hand (or deeper than it was); a refused step is tried
// once more at half its size. A turn clears the blend only if it also
// clears with the frame rounded as the stream will carry it
// (round_legs_to_grid, then the encoder's grid). The first turn that
// clears, or else the one that leaves the blend clearest, is kept.
// `turned`: an earlier call turned this frame (the frame is then drawn as
// sent even when it clears unrounded). True when `a` changed.
inline constexpr int kDrawnSteps = 6;  // t = 1/6, 2/6, ..., 1
inline constexpr float kDrawnStepDeg = 4.0f;
inline constexpr float kDrawnMostDeg = 32.0f;
bool keep_legs_apart_drawn(const LegBlend& legs, const SkeletonDef& skel, const proto::Quantizer* grid,
                           const PlayerPose& last, std::span<const float> last_angles, const DrawnRoot& now,
                           const bool planted[2], std::span<float> a, bool turned = false);

// The legs' least clearance (m; LegBlend::clearance) as the clients draw
// the frame from `last` to `now`, `a`, over the whole of it.
float drawn_leg_clearance(const LegBlend& legs, const PlayerPose& last, const DrawnRoot& now,
                          std::span<const float> a);

// Whether the legs come no clearer than `beat` anywhere as the clients draw
// the frame, drawn only as far as it takes to tell (first at `first`,
// unless it is NaN): how the check passes over a candidate turn. Without
// `first`, the same answer as drawn_leg_clearance(...) <= beat (where no
// point drawn is NaN).
bool drawn_leg_beaten(const LegBlend& legs, const PlayerPose& last, const DrawnRoot& now,
                      std::span<const float> a, float beat, float first = NAN);

// `pose` as the stream carries it: its root, heading and angles on the
// grid of `grid` (proto/SPEC.md section 3), as a client decodes it.
PlayerPose as_streamed(const proto::Quantizer& grid, const PlayerPose& pose);

}  // namespace mc::anim
