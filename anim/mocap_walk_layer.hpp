// The mocap mode's slow walk inside animate_player (motion_source.hpp): a
// player walking forwards between 0.3 and 1.5 m/s (hysteresis: 0.15 to 1.72
// once on) takes its legs, pelvis, torso lean and arms from the source's
// captured walk, cross-faded with the keyframe gait over 0.25 s.
//
// Feet: a foot the capture plants (within 2 cm of the lower foot, lifted at
// 6 cm) is held where it landed, and the swing that follows starts from the
// held spot (the offset fades over 0.2 s); beyond 25 cm from the capture's
// foot it lets go until its next step. Held feet are handed to locomotion
// (take_over_feet), which resumes from them. Cadence guard: a foot lands at
// most once per 0.45 s, also while fading and for a second after, so the
// human cadence cap holds across the switch of gaits.
//
// Runs only when PlayerFrameInput::source is set; body space as LegPoseJob.
#pragma once

#include <span>

#include "anim/leg_pose_job.hpp"
#include "anim/player_animation.hpp"

namespace mc::anim {

// `heading` is this frame's rate-limited heading; `a` the angles so far
// (keyframe upper body), `pelvis_h`, `feet` and `planted` locomotion's, all
// blended towards the capture in place.
void mocap_walk(PlayerAnim& ctx, const PlayerFrameInput& in, float heading, std::span<float> a, float& pelvis_h,
                FootTarget feet[2], bool planted[2]);

}  // namespace mc::anim
