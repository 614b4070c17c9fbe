// Feet in the air keep off the grass (issue 23). A foot that no footstep
// holds and that travels with its sole within a few centimetres of the
// grass reads as a foot sliding over it, whatever the animation meant: a
// foot just off the grass or about to land that the clients' blend between
// two frames drags through the contact height, a swing that crosses the
// other leg low in a turn, a foot handed back from an action. Before the
// legs are solved, such a foot's ankle target is raised until the sole
// it asks for is kSwingClearM up. Human skeleton only; no I/O.
#pragma once

namespace mc::anim {

// A foot in the air that moves further than this over the grass in a frame
// (m; 1 m/s at 20 Hz) keeps its sole kSwingClearM up: clear of the contact
// height (3 cm) by a margin for the clients' blend, which takes a sole
// leaving the grass or landing on it a third of its way in a third of the
// frame (proto/SPEC.md 4.7). 6.5 and 8 cm took the 60 Hz sliding further
// down but brought ankle pops and floating bodies (anim/README.md).
inline constexpr float kSkimStepM = 0.05f;
inline constexpr float kSwingClearM = 0.05f;
// After the joint speed limit such a foot's ankle may turn this far (deg)
// past its pitch towards level to keep the sole kSwingClearM up
// (player_animation.cpp). With 8 deg, as far as a sole pitched into the
// grass turns, game 2's 9+ m/s band at 20 Hz was 0.50 m/s; with 20 deg
// 0.39 (50 deg gave the same).
inline constexpr float kSkimLevelDeg = 20.0f;

// Whether a foot in the air whose ankle target is `ankle_height` m up and
// `travel_m` from where its ankle was on the last frame (over the grass)
// may need raising: no corner of the foot's box is further from the ankle
// than its centre's offset plus its half diagonal. Most feet in the air
// are higher.
bool may_skim(float ankle_height, float travel_m);

// How far to raise an ankle target `ankle_height` m up whose sole is asked
// for at `pitch_deg` (LegPoseJob's FootTarget; level sideways) so that the
// sole's lowest corner is kSwingClearM up: 0 when it is. The leg's solution
// gives that sole unless the ankle's limits hold it off its pitch or level
// (a leg crossing the other); posing the solution to catch those too cost
// 3-4 % of the animation's time for 0.01-0.02 m/s of the 60 Hz sliding.
float swing_lift(float ankle_height, float pitch_deg);

}  // namespace mc::anim
